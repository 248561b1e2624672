#pragma once
// The plots of one run folder. Each is a draw function that reads the run's files and
// writes <id>.gp and its CSVs into the plots folder and <id>.png one level up (the run
// folder's top level), plus a registration in run_plots() saying when it applies: adding a
// plot is one function here and one line there.
#include <string>

#include "analysis/run_files.hpp"
#include "plot/figure_files.hpp"

namespace swarmagg {

struct RunPlot {
  std::string id;  // file stem: <id>.png, plots/<id>.gp
  std::string what;
  bool (*applies)(const RunFiles&);
  void (*draw)(const RunFiles&, const FigureFiles&);
};

// NOA over time: replicate mean with its 95% confidence band, the replicates as thin lines
// when there are at most kThinLineReplicates, and each model variant's NOA from model.csv.
inline constexpr int kThinLineReplicates = 10;
void draw_noa_over_time(const RunFiles& run, const FigureFiles& files);

// Searching, waiting, leaving (and, for Soysal worlds, approaching) agents over time, mean
// over replicates.
void draw_states_over_time(const RunFiles& run, const FigureFiles& files);

// Aggregates of each size at the end, per replicate (mean), with each model variant's
// expected size distribution at the last step ("aggregates:<m>" in model.csv).
void draw_final_sizes(const RunFiles& run, const FigureFiles& files);

// Soysal worlds: time fraction per partition against the model variants (plot_partitions).
void draw_run_partitions(const RunFiles& run, const FigureFiles& files);

}  // namespace swarmagg
