#pragma once
// Runs a sweep (or one shard of it) on this machine: the runs that are not complete, in
// parallel threads, one run per thread at a time, each into its own folder
// (<out>/runs/<point id>/rep-<k>/, see sweep_runs.hpp) with the outputs of `swarmagg run`.
// Running it again skips complete runs and redoes the others. On SIGINT/SIGTERM the
// threads stop, runs in progress leave nothing behind, completed runs stay, and
// Interrupted is thrown.
#include <filesystem>
#include <vector>

#include "sweep/shard.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_runs.hpp"

namespace swarmagg {

struct SweepOptions {
  std::filesystem::path out;
  int threads = 0;  // 0: the machine's cores
  Shard shard;
  bool progress = false;  // a progress line on stderr (run/progress_line.hpp)
  bool plots = false;  // draw each run's own plots (run_plots.hpp); the caller checks for gnuplot
  // Replace runs whose folders hold a complete run of another world (the sweep's base world,
  // seed or values changed since); without it they are refused, naming one.
  bool replace_outdated = false;
};

struct SweepReport {
  int selected = 0;          // runs of the sweep in this shard
  int already_complete = 0;  // skipped
  int ran = 0;
  int threads = 1;
  double wall_seconds = 0.0;
};

// The runs of `runs` that belong to `shard`, in index order.
std::vector<SweepRun> shard_runs(std::vector<SweepRun> runs, Shard shard);

SweepReport run_sweep(const SweepPlan& plan, const SweepOptions& options);

}  // namespace swarmagg
