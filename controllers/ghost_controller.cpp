#include "controllers/ghost_controller.hpp"

namespace swarmagg {

void GhostController::decide(const ControllerInput& input, SwarmState& swarm,
                             const CounterRng& rng, std::span<MotionCommand> commands,
                             EventCounts& /*events*/) {
  turn_at_walls(input.reflections, swarm);
  const auto step = static_cast<std::uint64_t>(input.step);
  for (std::uint32_t i = 0; i < swarm.size(); ++i) {
    if (tumble_ > 0.0 && rng.uniform(step, i, Draw::Tumble) < tumble_) {
      swarm.heading[i] = random_heading(rng, input.step, i);
    }
    commands[i] = MotionCommand{swarm.heading[i] * speed_, 0, 0, 0};
  }
}

}  // namespace swarmagg
