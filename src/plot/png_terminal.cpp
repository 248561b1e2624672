#include "plot/png_terminal.hpp"

#include "plot/gnuplot.hpp"

namespace swarmagg {

std::string png_preamble(const PlotSize& size, const std::string& png_name,
                         const std::string& title) {
  return "set terminal pngcairo size " + std::to_string(size.width) + "," +
         std::to_string(size.height) + " font 'sans,10'\n" + "set output " +
         gnuplot_quote(png_name) + "\n" + "set datafile separator ','\n" + "set title " +
         gnuplot_quote(title) + " noenhanced\n" + "set grid\n";
}

}  // namespace swarmagg
