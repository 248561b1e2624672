#pragma once
// The ideal gas of the collision check (collision_mode: ghost): agents move straight and
// pass through each other; only a tumble (heading redrawn with a probability per step)
// breaks the periodic orbits a torus would otherwise allow. The engine counts encounters.
#include "controllers/controller.hpp"

namespace swarmagg {

class GhostController final : public Controller {
 public:
  GhostController(double speed, double tumble) : speed_(speed), tumble_(tumble) {}

  void decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
              std::span<MotionCommand> commands, EventCounts& events) override;

 private:
  double speed_;
  double tumble_;
};

}  // namespace swarmagg
