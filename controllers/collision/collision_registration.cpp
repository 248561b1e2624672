// The collision check of the paper (docs/controllers.md, Figs 7-8). Ghost mode: an ideal gas that
// only counts encounters and perceives nothing. Paper mode: a meeting pair aggregates and both
// leave at once (p = 1). Only the kinetic encounter rate models it.
#include "controllers/aggregation_controller.hpp"
#include "controllers/controller_registry.hpp"
#include "controllers/ghost_controller.hpp"

namespace swarmagg {
namespace {

bool ghost(const WorldSpec& spec) {
  return spec.controller.collision_mode == CollisionMode::Ghost;
}

double sensing_radius(const WorldSpec& spec) {
  return spec.robots.detection_radius;
}

double perception_radius(const WorldSpec& spec) {
  return ghost(spec) ? 0.0 : spec.robots.detection_radius;
}

ControllerRules rules(const WorldSpec& spec) {
  if (ghost(spec)) {
    ControllerRules r;
    r.allowed_states = state_bit(AgentState::Go);
    r.aggregates = false;
    r.model = ModelFamily::Encounters;
    return r;
  }
  ControllerRules r = aggregation_controller_rules(collision_paper_rules(spec));
  r.model = ModelFamily::Encounters;
  return r;
}

}  // namespace

ControllerRegistration collision_registration() {
  ControllerRegistration r;
  // Paper mode joins and leaves by its own rule; compaction is off in its rules but its
  // spacing is checked against the world and packs the observers' shapes.
  std::vector<std::string> reads = {"controller.collision_mode", "controller.tumble",
                                    "controller.isolated_wait", "controller.leave_timeout"};
  for (std::string& key : compaction_keys()) reads.push_back(std::move(key));
  r.world = {"collision", {}, sensing_radius, perception_radius, nullptr, std::move(reads)};
  r.make = [](const WorldSpec& spec) -> std::unique_ptr<Controller> {
    if (ghost(spec)) {
      return std::make_unique<GhostController>(spec.robots.speed, spec.controller.tumble);
    }
    return std::make_unique<AggregationController>(collision_paper_rules(spec));
  };
  r.rules = rules;
  return r;
}

}  // namespace swarmagg
