#pragma once
// The parameters of the aggregation state machine that Bayindir's, Soysal's and the
// collision experiment's controllers share (SPEC 3); each controller only builds these.
#include <optional>

#include "config/world_spec.hpp"

namespace swarmagg {

struct LeaveRule {
  LeaveLaw law = LeaveLaw::Constant;
  double base = 0.0;  // p (Bayindir) or p0 (Soysal): probability per step at size 1
  LeaveSize size_source = LeaveSize::Aggregate;
};

// SPEC 3 "Compaction": a waiting agent moves under F = sum_j (d_ij - spacing) u_ij from the
// waiting members of its aggregate it perceives, at min(v, gain |F|), standing below tolerance.
struct CompactionRule {
  bool enabled = false;
  double spacing = 2.0;     // u
  double gain = 1.0;        // per tu
  double tolerance = 0.05;  // u
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

// P_l(i) per step for an agent in an aggregate of `aggregate_size` agents that perceives
// `perceived` agents within s (which of the two is i is the rule's size_source).
double leave_probability(const LeaveRule& rule, int aggregate_size, int perceived);

AggregationRules bayindir_rules(const WorldSpec& spec);
AggregationRules soysal_rules(const WorldSpec& spec);
// The paper's collision check: pairs form (join: false) and leave at once (p = 1).
AggregationRules collision_paper_rules(const WorldSpec& spec);

}  // namespace swarmagg
