#pragma once
// Runs the replicates of a world in parallel threads. Each replicate owns all its mutable
// state and draws from its own generator, so the results are identical for any thread
// count. Results stay in memory, ordered by replicate (the rows, when not spooled to
// disk: run/timeseries_spool.hpp); run_folder writes them.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "observers/aggregate_geometry.hpp"
#include "observers/leave_tally.hpp"
#include "observers/timeseries_row.hpp"
#include "run/replicate_observer.hpp"

namespace swarmagg {

class TimeseriesSpool;

struct ReplicateOutcome {
  int index = 0;
  std::uint64_t seed = 0;           // the replicate's generator key
  std::vector<TimeseriesRow> rows;  // every recorded step's, unless spooled (RunOptions)
  TimeseriesRow final_row;          // the last step's, spooled or not
  std::vector<std::int32_t> final_aggregate_sizes;
  std::vector<AggregateShape> final_aggregates;         // by aggregate index, as the sizes
  LeaveTally leave;                                     // every LEAVE episode of the run
  std::map<std::string, std::int64_t> partition_steps;  // Soysal worlds
  std::uint64_t final_state_hash = 0;                   // run/state_hash.hpp, after the last step
  double wall_seconds = 0.0;
};

struct RunResult {
  std::vector<ReplicateOutcome> replicates;
  double wall_seconds = 0.0;
  int threads = 1;       // replicates run at once
  int step_threads = 1;  // threads inside each replicate's step
};

struct RunOptions {
  int threads = 0;        // 0: the world's run.threads, else the machine's cores
  bool progress = false;  // a progress line on stderr
  bool check = false;     // check invariants after every step (run/invariants.hpp)
  ObserverFactory observers;
  // Where the recorded rows go instead of ReplicateOutcome::rows: a long run holds none.
  TimeseriesSpool* timeseries = nullptr;
  // False, without `timeseries`: the rows are not held, only each replicate's final row is
  // kept (`rates`, which writes no timeseries). Spooled rows are spooled either way.
  bool keep_rows = true;
};

// `requested`, else the world's run.threads, else the machine's cores.
int resolve_threads(const WorldSpec& spec, int requested);

// The threads a run uses: `requested`, else the world's run.threads, else the machine's
// cores. Replicates run in parallel first; threads beyond one per replicate go inside the
// replicates' steps (a single large world then uses them all). Results do not depend on it.
struct ThreadPlan {
  int replicates_at_once = 1;
  int step_threads = 1;
};
ThreadPlan plan_threads(const WorldSpec& spec, int requested);

// How one replicate runs; check, timeseries and keep_rows mean what RunOptions' fields of the
// same names mean.
struct ReplicateRunOptions {
  bool check = false;
  int step_threads = 1;  // threads inside the replicate's step (ThreadPlan::step_threads)
  TimeseriesSpool* timeseries = nullptr;
  bool keep_rows = true;
};

ReplicateOutcome run_replicate(const WorldSpec& spec, int index, ReplicateObserver* observer,
                               const ReplicateRunOptions& how = {});
RunResult run_world(const WorldSpec& spec, const RunOptions& options);

}  // namespace swarmagg
