#include "compare/arm_comparison.hpp"

#include "controllers/controller_registry.hpp"

namespace swarmagg {
namespace {

LeaveSplit split_attempts(const std::vector<std::vector<LeaveAttempt>>& per_replicate) {
  LeaveSplit split;
  for (const auto& attempts : per_replicate) {
    for (const LeaveAttempt& a : attempts) {
      (a.rim ? split.rim_attempts : split.inside_attempts) += 1;
      if (a.got_out) (a.rim ? split.rim_out : split.inside_out) += 1;
    }
  }
  return split;
}

}  // namespace

ArmSummary summarize_arm(const ArmResult& arm) {
  ArmSummary s;
  s.label = arm.label;
  for (const ReplicateOutcome& r : arm.run.replicates) {
    const TimeseriesRow& last = r.rows.back();
    s.final_noa.push_back(last.noa);
    for (std::int32_t size : r.final_aggregate_sizes) s.final_sizes.push_back(size);
    if (last.time > 0.0)
      s.encounter_rates.push_back(static_cast<double>(last.events.encounters) / last.time);
  }
  s.noa = mean_interval(s.final_noa);
  s.encounter_rate = mean_interval(s.encounter_rates);
  s.leave = split_attempts(arm.leave_attempts);
  return s;
}

Comparison compare_arms(const ArmResult& a, const ArmResult& b, int rim_below) {
  Comparison c;
  c.a = summarize_arm(a);
  c.b = summarize_arm(b);
  c.noa_difference = welch_interval(c.a.final_noa, c.b.final_noa);
  c.ks_noa = ks_two_sample(c.a.final_noa, c.b.final_noa);
  c.ks_sizes = ks_two_sample(c.a.final_sizes, c.b.final_sizes);
  c.rim_below = rim_below;
  c.has_leaving =
      controller_rules(a.spec).leaving_happens || controller_rules(b.spec).leaving_happens;
  return c;
}

bool Comparison::differs() const {
  return noa_difference.p_value < kSignificance || ks_noa.p_value < kSignificance ||
         ks_sizes.p_value < kSignificance;
}

}  // namespace swarmagg
