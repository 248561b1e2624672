#pragma once
// The plots of a merged sweep (sweep_summary.csv): for each swept parameter,
// final-noa-vs-<key>.png, the final NOA's mean over replicates against the parameter with
// the 95% confidence interval of the mean at each point, one line per combination of the
// other parameters. Like a run's plots, the PNGs go to the top of `out`, their scripts
// and CSVs to `out`/plots/.
#include <filesystem>

#include "plot/png_terminal.hpp"
#include "plot/run_plots.hpp"

namespace swarmagg {

inline constexpr const char* kSweepSummaryFile = "sweep_summary.csv";
// Every sweep plot's files (PNG, script, CSV) are named by this and the parameter's key.
inline constexpr const char* kSweepPlotPrefix = "final-noa-vs-";

// Throws InputError when the folder has no sweep_summary.csv (or it holds no noa rows).
PlotOutcome draw_sweep_plots(const std::filesystem::path& sweep_folder,
                             const std::filesystem::path& out, const PlotSize& size = {});

}  // namespace swarmagg
