#pragma once
// One side of a comparison: a world (usually the same world on one engine) run with the
// run's replicates and seeds. Each replicate's outcome carries its LEAVE episodes and final
// aggregate shapes (run/world_runner.hpp), which the comparison reads, and the arm counts
// where each replicate's aggregates came from (observers/aggregate_lineage.hpp).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "observers/aggregate_lineage.hpp"
#include "run/timeseries_spool.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

struct ArmResult {
  std::string label;  // e.g. "kinematic"
  WorldSpec spec;
  RunResult run;
  std::vector<LineageCounts> lineage;  // by replicate, over the whole run
  // Where the replicates' rows went instead of run.replicates[k].rows (null: kept there).
  std::unique_ptr<TimeseriesSpool> timeseries;
};

// With `out`, the rows are spooled to disk while the replicates run (a long comparison holds
// none in memory): to out/<label>/timeseries.csv once the arm's folder is written, through
// temporaries in `out` itself.
ArmResult run_arm(const std::string& label, const WorldSpec& spec, bool progress = false,
                  const std::filesystem::path& out = {});

}  // namespace swarmagg
