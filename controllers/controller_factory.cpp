#include "controllers/aggregation_controller.hpp"
#include "controllers/controller.hpp"
#include "controllers/ghost_controller.hpp"
#include "engine/engine.hpp"

namespace swarmagg {

void turn_at_walls(std::span<const std::uint8_t> reflections, SwarmState& swarm) {
  for (std::size_t i = 0; i < reflections.size(); ++i) {
    if (reflections[i] & ReflectedX) swarm.heading[i].x = -swarm.heading[i].x;
    if (reflections[i] & ReflectedY) swarm.heading[i].y = -swarm.heading[i].y;
  }
}

std::unique_ptr<Controller> make_controller(const WorldSpec& spec) {
  switch (spec.controller.type) {
    case ControllerType::Bayindir:
      return std::make_unique<AggregationController>(bayindir_rules(spec));
    case ControllerType::Soysal:
      return std::make_unique<AggregationController>(soysal_rules(spec));
    case ControllerType::Collision:
      if (spec.controller.collision_mode == CollisionMode::Ghost) {
        return std::make_unique<GhostController>(spec.robots.speed, spec.controller.tumble);
      }
      return std::make_unique<AggregationController>(collision_paper_rules(spec));
  }
  return nullptr;
}

}  // namespace swarmagg
