#pragma once
// The leave-timeout series of `reproduce` (docs/models-returns.md): the 10- and 20-agent
// Soysal worlds run again with leave_timeout 10, 20, 30 and 50 tu, into
// <out>/timeout-series/runs/<world>-timeout-<T>/ (the paper's own timeout is the figure's
// run in <out>/runs/<world>/), each compared with every partition model
// variant beside its noise floor. Once leave_timeout x v exceeds the approach radius, leavers
// no longer perceive the aggregate they left when the timeout ends: leaving stops being an
// excursion, and the paper's variants can fit. <out>/timeout-series.csv holds the numbers,
// <out>/plots/timeout-series.png each variant's error (and floor) against the timeout.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/partition_comparison.hpp"
#include "analysis/run_stationarity.hpp"
#include "plot/png_terminal.hpp"
#include "rates/rate_rows.hpp"
#include "reproduce/reproduce.hpp"

namespace swarmagg {

inline constexpr double kLeaveTimeouts[] = {10.0, 20.0, 30.0, 50.0};
inline constexpr const char* kTimeoutWorlds[] = {"soysal-10-constant", "soysal-20-constant"};
inline constexpr const char* kTimeoutFolder = "timeout-series";

struct TimeoutPoint {
  std::string world;  // the paper world it varies
  int agents = 0;
  double leave_timeout = 0.0;
  double duration = 0.0;  // tu per replicate
  int replicates = 0;
  PartitionComparison comparison = {};
  std::vector<RateRow> rates = {};
  NoaTrend trend = {};
  bool reused = false;
  bool paper_run = false;     // the paper world's own run (its figure's), not one of the series'
  double wall_seconds = 0.0;  // this reproduce's time on the point (reading a reused run back)
  // The simulation's own wall time (its summary.json), also for a run reused from a figure.
  double simulation_seconds = 0.0;
};

// Whether the options ask for the series (no --only, or an --only that names it).
bool timeout_series_selected(const ReproduceOptions& options);

// The series' runs, in the order of the CSV and the report: each world, each timeout.
struct TimeoutRun {
  std::string world;
  double leave_timeout = 0.0;
};
std::vector<TimeoutRun> timeout_runs();

// The paper world with the point's timeout and the series' run length.
WorldSpec timeout_world(const ReproduceOptions& options, const TimeoutRun& run);

// Whether the point changes nothing in its paper world (the paper's own timeout at the
// paper's length): then it is the figure's own run, <out>/runs/<world>/, not run twice.
bool is_paper_run(const ReproduceOptions& options, const TimeoutRun& run);

// Runs one point of the series (or reuses its complete run) with `run_threads` threads.
TimeoutPoint run_timeout_point(const ReproduceOptions& options, const TimeoutRun& run,
                               int run_threads);

std::string timeout_series_csv(const std::vector<TimeoutPoint>& points);

void plot_timeout_series(const std::filesystem::path& plots, const PlotSize& size,
                         const std::vector<TimeoutPoint>& points);

}  // namespace swarmagg
