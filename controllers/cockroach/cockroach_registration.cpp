// The neighbour-count (cockroach) controller's registration: its type name, its two keys, its
// factory and its rules (docs/controllers.md walks through this file).
#include "config/world_keys.hpp"
#include "controllers/cockroach/cockroach_controller.hpp"
#include "controllers/controller_registry.hpp"

namespace swarmagg {
namespace {

// Defaults after the shape Jeanson et al. (2005) measured: stopping grows and leaving falls
// with the number of waiting neighbours; per step of dt.
const WorldKey& stop_key() {
  static const WorldKey key = described(
      number_list_key("controller.stop_probability", {0.05, 0.2, 0.5}, 0.0, 1.0, "cockroach"),
      "cockroach: probability per step that a searcher perceiving n waiting agents stops, "
      "entry n (from 1; the last for more)");
  return key;
}

const WorldKey& leave_key() {
  static const WorldKey key =
      described(number_list_key("controller.leave_probability", {0.05, 0.005, 0.001, 0.0002}, 0.0,
                                1.0, "cockroach"),
                "cockroach: probability per step that a waiting agent perceiving n waiting agents "
                "leaves, entry n (from 0; the last for more)");
  return key;
}

double detection_radius(const WorldSpec& spec) {
  return spec.robots.detection_radius;
}

std::unique_ptr<Controller> make(const WorldSpec& spec) {
  CockroachParameters p;
  p.stop_probability = number_list(spec, stop_key());
  p.leave_probability = number_list(spec, leave_key());
  p.leave_timeout = spec.controller.leave_timeout;
  p.speed = spec.robots.speed;
  p.dt = spec.engine.dt;
  p.detection_radius = spec.robots.detection_radius;
  p.compaction = compaction_rule(spec);
  return std::make_unique<CockroachController>(std::move(p));
}

ControllerRules rules(const WorldSpec& spec) {
  const std::vector<double>& leave = number_list(spec, leave_key());
  ControllerRules r;
  r.allowed_states =
      state_bit(AgentState::Go) | state_bit(AgentState::Wait) | state_bit(AgentState::Leave);
  r.joins = true;
  r.leaves = true;
  r.leaving_happens = std::any_of(leave.begin(), leave.end(), [](double p) { return p > 0.0; });
  r.compacts = compaction_rule(spec).enabled;
  r.model = ModelFamily::None;  // neither paper model describes it
  return r;
}

}  // namespace

ControllerRegistration cockroach_registration() {
  ControllerRegistration r;
  std::vector<std::string> reads = {"controller.leave_timeout"};
  for (std::string& key : compaction_keys()) reads.push_back(std::move(key));
  r.world = {"cockroach", {stop_key(), leave_key()}, detection_radius, detection_radius,
             nullptr,     std::move(reads)};
  r.make = make;
  r.rules = rules;
  return r;
}

}  // namespace swarmagg
