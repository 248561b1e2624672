// Soysal's GO / APPROACH / WAIT / LEAVE controller (docs/controllers.md): Bayindir's state machine
// plus APPROACH within s_a, with a size-dependent leave law. Its worlds record partitions and are
// described by the partition model.
#include "config/world_keys.hpp"
#include "controllers/aggregation_controller.hpp"
#include "controllers/controller_registry.hpp"

namespace swarmagg {
namespace {

double sensing_radius(const WorldSpec& spec) {
  return std::max(spec.robots.detection_radius, spec.controller.approach_radius);
}

std::optional<KeyProblem> check(const WorldSpec& spec) {
  const double s = spec.robots.detection_radius;
  if (spec.controller.approach_radius > s) return std::nullopt;
  return KeyProblem{"controller.approach_radius",
                    "must exceed robots.detection_radius (" + format_number(s) + ")"};
}

ControllerRules rules(const WorldSpec& spec) {
  ControllerRules r = aggregation_controller_rules(soysal_rules(spec));
  r.records_partitions = true;
  r.model = ModelFamily::Soysal;
  return r;
}

}  // namespace

ControllerRegistration soysal_registration() {
  ControllerRegistration r;
  r.world = {"soysal",
             {},
             sensing_radius,
             sensing_radius,
             check,
             aggregation_keys({"controller.p0", "controller.leave_law", "controller.leave_size",
                               "controller.approach_radius", "controller.tumble"})};
  r.make = [](const WorldSpec& spec) -> std::unique_ptr<Controller> {
    return std::make_unique<AggregationController>(soysal_rules(spec));
  };
  r.rules = rules;
  r.leave_probability_at_size = [](const WorldSpec& spec, int size) {
    return member_leave_probability(soysal_rules(spec), size);
  };
  return r;
}

}  // namespace swarmagg
