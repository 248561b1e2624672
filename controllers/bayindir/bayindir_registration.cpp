// Bayindir's GO / WAIT / LEAVE controller (docs/controllers.md): the aggregation state machine with
// a constant leave probability p per step; the experiment rules switch joining and leaving.
#include "controllers/aggregation_controller.hpp"
#include "controllers/controller_registry.hpp"

namespace swarmagg {
namespace {

double detection_radius(const WorldSpec& spec) {
  return spec.robots.detection_radius;
}

ControllerRules rules(const WorldSpec& spec) {
  ControllerRules r = aggregation_controller_rules(bayindir_rules(spec));
  r.model = ModelFamily::Bayindir;
  return r;
}

}  // namespace

ControllerRegistration bayindir_registration() {
  ControllerRegistration r;
  r.world = {"bayindir",       {},      detection_radius,
             detection_radius, nullptr, aggregation_keys({"controller.p_leave"})};
  r.make = [](const WorldSpec& spec) -> std::unique_ptr<Controller> {
    return std::make_unique<AggregationController>(bayindir_rules(spec));
  };
  r.rules = rules;
  r.leave_probability_at_size = [](const WorldSpec& spec, int size) {
    return member_leave_probability(bayindir_rules(spec), size);
  };
  return r;
}

}  // namespace swarmagg
