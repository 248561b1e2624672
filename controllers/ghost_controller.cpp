#include "controllers/ghost_controller.hpp"

namespace swarmagg {

void GhostController::decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
                             std::span<MotionCommand> commands, EventCounts& /*events*/) {
  turn_at_walls(input.reflections, swarm);
  const auto n = static_cast<std::uint32_t>(swarm.size());
  if (tumble_ > 0.0) {
    const auto step = static_cast<std::uint64_t>(input.step);
    for (std::uint32_t i = 0; i < n; ++i) {
      if (rng.uniform(step, i, Draw::Tumble) < tumble_) {
        swarm.heading[i] = random_heading(rng, input.step, i);
      }
    }
  }
  // A separate plain loop over raw arrays: the compiler keeps nothing but the copy in it.
  const Vec2* heading = swarm.heading.data();
  MotionCommand* out = commands.data();
  const double speed = speed_;
  for (std::uint32_t i = 0; i < n; ++i) out[i] = MotionCommand{heading[i] * speed, 0, 0, 0};
}

}  // namespace swarmagg
