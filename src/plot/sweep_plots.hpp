#pragma once
// The plots of a merged sweep (sweep_summary.csv): for each swept parameter,
// final-noa-vs-<key>.png, the final NOA's mean over replicates against the parameter with
// the 95% confidence interval of the mean at each point, one line per combination of the
// other parameters. Like a run's plots, the PNGs go to the top of `out`, their scripts
// and CSVs to `out`/plots/.
#include <filesystem>
#include <string>

#include "plot/figure_files.hpp"
#include "plot/png_terminal.hpp"
#include "plot/run_plots.hpp"

namespace swarmagg {

inline constexpr const char* kSweepSummaryFile = "sweep_summary.csv";
// The files of the sweep plot against parameter `key`: out/final-noa-vs-<key>.png, its script
// and CSV in out/plots/.
FigureFiles sweep_plot_files(const std::filesystem::path& out, const std::string& key,
                             const PlotSize& size = {});

// Throws InputError when the folder has no sweep_summary.csv (or it holds no noa rows).
PlotOutcome draw_sweep_plots(const std::filesystem::path& sweep_folder,
                             const std::filesystem::path& out, const PlotSize& size = {});

}  // namespace swarmagg
