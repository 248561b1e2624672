#pragma once
// One side of a comparison: a world (usually the same world on one engine) run with the
// run's replicates and seeds. Each replicate's outcome carries its LEAVE episodes and final
// aggregate shapes (run/world_runner.hpp), which the comparison reads.
#include <string>

#include "config/world_spec.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

struct ArmResult {
  std::string label;  // e.g. "kinematic"
  WorldSpec spec;
  RunResult run;
};

ArmResult run_arm(const std::string& label, const WorldSpec& spec, bool progress = false);

}  // namespace swarmagg
