#pragma once
// Draws every plot that applies to a finished run folder (run_plot.hpp lists them): the
// PNGs at the top of `out`, each gnuplot script and the CSVs it reads in `out`/plots/, so
// a user can restyle a plot and re-run gnuplot there. `swarmagg run` draws into the run
// folder itself; `swarmagg plot RUN_DIR --out DIR` redraws from the same files elsewhere,
// byte for byte the same CSVs and scripts.
#include <filesystem>
#include <string>
#include <vector>

#include "plot/plot_collection.hpp"
#include "plot/png_terminal.hpp"
#include "plot/run_plot.hpp"

namespace swarmagg {

const std::vector<RunPlot>& run_plots();

inline constexpr const char* kPlotsFolder = "plots";

// Throws InputError when `run_folder` holds no complete run, std::runtime_error when
// gnuplot is missing (check gnuplot_available() first to skip quietly).
PlotOutcome draw_run_plots(const std::filesystem::path& run_folder,
                           const std::filesystem::path& out, const PlotSize& size = {});

// Why plots cannot be drawn on this machine, or empty when they can (gnuplot on PATH).
std::string plots_unavailable_reason();

}  // namespace swarmagg
