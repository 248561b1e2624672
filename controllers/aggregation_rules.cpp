#include "controllers/aggregation_rules.hpp"

#include "config/leave_law.hpp"

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
  rules.compaction = compaction_rule(spec);
  return rules;
}

}  // namespace

std::vector<std::string> aggregation_keys(std::vector<std::string> own) {
  std::vector<std::string> keys = {"controller.join", "controller.leave",
                                   "controller.isolated_wait", "controller.leave_timeout"};
  for (std::string& key : compaction_keys()) keys.push_back(std::move(key));
  for (std::string& key : own) keys.push_back(std::move(key));
  return keys;
}

double leave_probability(const LeaveRule& rule, int aggregate_size, int perceived) {
  const int size = rule.size_source == LeaveSize::Neighbours ? perceived + 1 : aggregate_size;
  return leave_probability(rule.law, rule.base, size);
}

ControllerRules aggregation_controller_rules(const AggregationRules& rules) {
  ControllerRules r;
  r.allowed_states = state_bit(AgentState::Go) | state_bit(AgentState::Wait);
  if (rules.approach_radius) r.allowed_states |= state_bit(AgentState::Approach);
  if (rules.leave) r.allowed_states |= state_bit(AgentState::Leave);
  r.joins = rules.join;
  r.leaves = rules.leave;
  r.leaving_happens = rules.leave && rules.leave_rule.base > 0.0;
  r.partners_only = !rules.join;
  r.compacts = rules.compaction.enabled;
  return r;
}

double member_leave_probability(const AggregationRules& rules, int size) {
  return leave_probability(rules.leave_rule, size, size - 1);
}

AggregationRules bayindir_rules(const WorldSpec& spec) {
  AggregationRules rules = common_rules(spec);
  rules.leave_rule = {LeaveLaw::Constant, spec.controller.p_leave, LeaveSize::Aggregate};
  return rules;
}

AggregationRules soysal_rules(const WorldSpec& spec) {
  AggregationRules rules = common_rules(spec);
  rules.leave_rule = {spec.controller.leave_law, spec.controller.p0, spec.controller.leave_size};
  rules.approach_radius = spec.controller.approach_radius;
  // A searcher that perceives nobody may redraw its heading (0 by default: it keeps it, and
  // may run a closed path on the torus past every aggregate).
  rules.tumble = spec.controller.tumble;
  return rules;
}

AggregationRules collision_paper_rules(const WorldSpec& spec) {
  AggregationRules rules = common_rules(spec);
  rules.join = false;
  rules.leave = true;
  rules.leave_rule = {LeaveLaw::Constant, 1.0, LeaveSize::Aggregate};
  rules.tumble = spec.controller.tumble;
  // Its pairs wait for a single step before leaving, and it checks kinetic theory on moving
  // agents, not aggregates: compaction would only nudge each pair once.
  rules.compaction.enabled = false;
  return rules;
}

}  // namespace swarmagg
