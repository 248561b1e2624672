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

// The legend above the plot, three entries a row: the data keep the plot's full width,
// long model-variant names are never cut, and (unlike a legend below) it never runs into
// the x axis label.
inline constexpr const char* kKeyAbovePlot =
    "set key outside top center horizontal maxcols 3 Left reverse noenhanced\n";

std::string png_preamble(const PlotSize& size, const std::string& png_name,
                         const std::string& title);

}  // namespace swarmagg
