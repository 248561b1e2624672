#pragma once
// The opening lines every generated PNG plot shares: the cairo PNG terminal at a given
// pixel size, the output file (relative, as run_gnuplot runs in the script's folder) and
// comma-separated data with one header line to skip.
#include <string>

namespace swarmagg {

struct PlotSize {
  int width = 900;
  int height = 600;
};

std::string png_preamble(const PlotSize& size, const std::string& png_name,
                         const std::string& title);

}  // namespace swarmagg
