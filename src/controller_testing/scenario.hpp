#pragma once
// The scenario runner of the controller test harness (docs/controllers.md): a tiny world run
// for a number of steps on the engine it names, with every invariant checked after every step
// (run/invariants.hpp: the states, events and aggregates must obey the controller's rules).
// A test then expects states, events or aggregates of the end, or of every step through
// `each_step`. Unlike ControllerFixture (one decision, no engine), this runs the whole step:
// controller, engine, aggregate tracking.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/event_counts.hpp"
#include "core/agent_state.hpp"
#include "core/vec2.hpp"

namespace swarmagg {
class Replicate;
}

namespace swarmagg::testing {

// A world from YAML text (only what differs from the defaults) and `--set` style overrides.
WorldSpec scenario_world(const std::string& yaml, const std::vector<std::string>& overrides = {});

struct ScenarioEnd {
  std::int64_t steps = 0;
  std::vector<AgentState> states;
  std::vector<Vec2> positions;
  EventCounts events;
  std::vector<std::int32_t> aggregate_sizes;  // by aggregate index
};

// Runs replicate `replicate` of `world` for `steps` steps; `each_step` (if given) sees the
// replicate after every step. Throws InvariantViolation when a step breaks a rule.
ScenarioEnd run_scenario(const WorldSpec& world, std::int64_t steps,
                         const std::function<void(const Replicate&)>& each_step = {},
                         int replicate = 0);

}  // namespace swarmagg::testing
