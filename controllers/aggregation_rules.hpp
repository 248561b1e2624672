#pragma once
// The parameters of the aggregation state machine that Bayindir's, Soysal's and the
// collision experiment's controllers share (docs/controllers.md); each controller only builds
// these.
#include <optional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/controller_rules.hpp"
#include "controllers/compaction.hpp"

namespace swarmagg {

struct LeaveRule {
  LeaveLaw law = LeaveLaw::Constant;
  double base = 0.0;  // p (Bayindir) or p0 (Soysal): probability per step at size 1
  LeaveSize size_source = LeaveSize::Aggregate;
};

struct AggregationRules {
  bool join = true;   // searching agents may join waiting agents
  bool leave = true;  // waiting agents may leave
  bool resume_when_isolated = true;
  LeaveRule leave_rule;
  double leave_timeout = 10.0;  // tu
  double speed = 1.0;
  double dt = 0.1;
  double detection_radius = 4.0;
  std::optional<double> approach_radius;  // Soysal's APPROACH state
  double tumble = 0.0;                    // heading redraw probability per step while GO
  CompactionRule compaction;
};

// The shared controller.* keys every rule set below reads (joining, leaving, the timeout, the
// isolated wait, compaction), followed by `own`: a registration's shared_keys.
std::vector<std::string> aggregation_keys(std::vector<std::string> own);

// P_l(i) per step for an agent in an aggregate of `aggregate_size` agents that perceives
// `perceived` agents within s (which of the two is i is the rule's size_source).
double leave_probability(const LeaveRule& rule, int aggregate_size, int perceived);

// What a controller built on these rules allows (its registration adds the model and outputs):
// GO and WAIT, APPROACH with an approach radius, LEAVE when agents may leave; joining,
// leaving, partners-only linking without joining, and compaction as the rules say.
ControllerRules aggregation_controller_rules(const AggregationRules& rules);

// A member's leave probability per step in an aggregate of `size` that perceives the other
// members (ControllerRegistration::leave_probability_at_size).
double member_leave_probability(const AggregationRules& rules, int size);

AggregationRules bayindir_rules(const WorldSpec& spec);
AggregationRules soysal_rules(const WorldSpec& spec);
// The paper's collision check: pairs form (join: false) and leave at once (p = 1).
AggregationRules collision_paper_rules(const WorldSpec& spec);

}  // namespace swarmagg
