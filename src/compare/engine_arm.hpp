#pragma once
// One side of a comparison: a world (usually the same world on one engine) run with the
// run's replicates and seeds, with a LEAVE-attempt observer on every replicate.
#include <string>
#include <vector>

#include "compare/leave_attempts.hpp"
#include "config/world_spec.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

struct ArmResult {
  std::string label;  // e.g. "kinematic"
  WorldSpec spec;
  RunResult run;
  std::vector<std::vector<LeaveAttempt>> leave_attempts;  // per replicate
};

ArmResult run_arm(const std::string& label, const WorldSpec& spec, int rim_below,
                  bool progress = false);

}  // namespace swarmagg
