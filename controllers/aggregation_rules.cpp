#include "controllers/aggregation_rules.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

AggregationRules common_rules(const WorldSpec& spec) {
  AggregationRules rules;
  rules.join = spec.controller.join;
  rules.leave = spec.controller.leave;
  rules.resume_when_isolated = spec.controller.isolated_wait == IsolatedWait::Resume;
  rules.leave_timeout = spec.controller.leave_timeout;
  rules.speed = spec.robots.speed;
  rules.dt = spec.engine.dt;
  rules.detection_radius = spec.robots.detection_radius;
  return rules;
}

int exponent_of(LeaveLaw law) {
  switch (law) {
    case LeaveLaw::Constant: return 0;
    case LeaveLaw::Inverse: return 1;
    case LeaveLaw::InverseSquare: return 2;
  }
  return 0;
}

}  // namespace

double leave_probability(const LeaveRule& rule, int aggregate_size, int perceived) {
  if (rule.size_exponent == 0) return rule.base;
  const int size = rule.size_source == LeaveSize::Neighbours ? perceived + 1 : aggregate_size;
  return rule.base / std::pow(static_cast<double>(std::max(size, 1)), rule.size_exponent);
}

AggregationRules bayindir_rules(const WorldSpec& spec) {
  AggregationRules rules = common_rules(spec);
  rules.leave_rule = {spec.controller.p_leave, 0, LeaveSize::Aggregate};
  return rules;
}

AggregationRules soysal_rules(const WorldSpec& spec) {
  AggregationRules rules = common_rules(spec);
  rules.leave_rule = {spec.controller.p0, exponent_of(spec.controller.leave_law),
                      spec.controller.leave_size};
  rules.approach_radius = spec.controller.approach_radius;
  return rules;
}

AggregationRules collision_paper_rules(const WorldSpec& spec) {
  AggregationRules rules = common_rules(spec);
  rules.join = false;
  rules.leave = true;
  rules.leave_rule = {1.0, 0, LeaveSize::Aggregate};
  rules.tumble = spec.controller.tumble;
  return rules;
}

}  // namespace swarmagg
