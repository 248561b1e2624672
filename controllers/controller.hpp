#pragma once
// A controller is the finite-state machine of every agent: perception in, motion commands
// out. It sees only what an agent's sensors give (neighbours within the sensing radius,
// wall bumpers) and the aggregate bookkeeping the model assumes agents know; it never sees
// an engine.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "config/world_spec.hpp"
#include "control_interface/controller_input.hpp"
#include "control_interface/event_counts.hpp"
#include "control_interface/motion_command.hpp"
#include "core/agent_state.hpp"
#include "core/rng.hpp"

namespace swarmagg {

class Controller {
 public:
  virtual ~Controller() = default;
  // Decides each agent's next state and fills its motion command; counts the aggregation
  // events the decision makes.
  virtual void decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
                      std::span<MotionCommand> commands, EventCounts& events) = 0;
};

// The controller `spec.controller.type` registered (controllers/controller_registry.hpp).
std::unique_ptr<Controller> make_controller(const WorldSpec& spec);

// A uniformly random unit heading for `agent` at `step`.
inline Vec2 random_heading(const CounterRng& rng, std::int64_t step, std::uint32_t agent,
                           Draw purpose = Draw::Heading) {
  constexpr double kTwoPi = 6.283185307179586;
  return from_angle(kTwoPi * rng.uniform(static_cast<std::uint64_t>(step), agent, purpose));
}

// The unit vector away from the agents within `radius` among `neighbours` (nearest first):
// opposite the sum of the offsets to them. None when they cancel out: when the sum is zero,
// or shorter than `enclosed_fraction` of the summed distances (an agent deep in a packed
// aggregate, whose sum points nowhere in particular; controllers/compaction.hpp).
std::optional<Vec2> heading_away(std::span<const Neighbour> neighbours, double radius,
                                 double enclosed_fraction);

// Mirrors headings the walls reflected during the last step.
void turn_at_walls(std::span<const std::uint8_t> reflections, SwarmState& swarm);

}  // namespace swarmagg
