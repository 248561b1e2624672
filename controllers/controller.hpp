#pragma once
// A controller is the finite-state machine of every agent: perception in, motion commands
// out. It sees only what an agent's sensors give (neighbours within the sensing radius,
// wall bumpers) and the aggregate bookkeeping the model assumes agents know; it never sees
// an engine.
#include <cstdint>
#include <memory>
#include <span>

#include "config/world_spec.hpp"
#include "core/agent_state.hpp"
#include "core/rng.hpp"
#include "engine/motion_command.hpp"
#include "engine/neighbour_lists.hpp"
#include "observers/aggregate_tracker.hpp"
#include "observers/event_counts.hpp"

namespace swarmagg {

struct ControllerInput {
  std::int64_t step = 0;
  const NeighbourLists& neighbours;
  std::span<const std::uint8_t> reflections;  // engine.hpp's Reflection bits
  const AggregateTracker& aggregates;         // of the states the decision starts from
  // Cumulative growths by the size of the aggregate joined ([m]; a searcher that joins a
  // pair formed in the same decision counts at m = 2), counted when not empty. Observers
  // (measured rates) read them; no decision depends on them.
  std::span<std::uint64_t> growths_by_size = {};
};

class Controller {
 public:
  virtual ~Controller() = default;
  // Decides each agent's next state and fills its motion command; counts the aggregation
  // events the decision makes.
  virtual void decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
                      std::span<MotionCommand> commands, EventCounts& events) = 0;
};

std::unique_ptr<Controller> make_controller(const WorldSpec& spec);

// A uniformly random unit heading for `agent` at `step`.
inline Vec2 random_heading(const CounterRng& rng, std::int64_t step, std::uint32_t agent,
                           Draw purpose = Draw::Heading) {
  constexpr double kTwoPi = 6.283185307179586;
  return from_angle(kTwoPi * rng.uniform(static_cast<std::uint64_t>(step), agent, purpose));
}

// Mirrors headings the walls reflected during the last step.
void turn_at_walls(std::span<const std::uint8_t> reflections, SwarmState& swarm);

}  // namespace swarmagg
