#pragma once
// The figures of one folder, drawn together by one gnuplot process (GnuplotBatch): each
// figure's script and CSVs are written first, then all PNGs are drawn, and a figure that
// fails is reported by name while the others stand.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "plot/figure_files.hpp"
#include "plot/gnuplot_batch.hpp"

namespace swarmagg {

struct PlotOutcome {
  std::vector<std::filesystem::path> drawn;  // the PNGs
  std::vector<std::string> failures;         // one message per plot gnuplot could not draw
};

class PlotCollection {
 public:
  // Runs `write` (which writes the figure's CSVs and calls run_gnuplot) with the drawing
  // deferred to draw(); a figure whose files cannot be written is a failure at once. A
  // damaged input the figure reads (a row of timeseries.csv cut short) is the command's bad
  // input, not one figure's failure: its InputError goes on to the caller.
  void prepare(const FigureFiles& files, const std::function<void(const FigureFiles&)>& write);
  // Draws every prepared figure. Throws std::runtime_error when gnuplot is missing.
  PlotOutcome draw();

 private:
  GnuplotBatch batch_;
  std::vector<FigureFiles> prepared_;
  PlotOutcome outcome_;
};

}  // namespace swarmagg
