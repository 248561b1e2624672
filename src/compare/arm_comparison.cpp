#include "compare/arm_comparison.hpp"

#include <stdexcept>
#include <string>

#include "controllers/controller_registry.hpp"
#include "run/aggregate_summary.hpp"

namespace swarmagg {

ArmSummary summarize_arm(const ArmResult& arm) {
  if (arm.lineage.size() != arm.run.replicates.size())
    throw std::logic_error("compare: the arm's lineage has " + std::to_string(arm.lineage.size()) +
                           " replicates, its run " + std::to_string(arm.run.replicates.size()));
  ArmSummary s;
  s.label = arm.label;
  s.lineage = arm.lineage;
  for (std::size_t k = 0; k < arm.run.replicates.size(); ++k) {
    const ReplicateOutcome& r = arm.run.replicates[k];
    const TimeseriesRow& last = r.final_row;
    s.final_noa.push_back(last.noa);
    for (std::int32_t size : r.final_aggregate_sizes) s.final_sizes.push_back(size);
    s.escapes.push_back({r.leave.escapes.total(), r.leave.attempts.total()});
    if (last.time <= 0.0) continue;
    const LineageCounts& l = arm.lineage[k];
    s.encounter_rates.push_back(static_cast<double>(last.events.encounters) / last.time);
    s.net_merge_rates.push_back((static_cast<double>(l.merges) - static_cast<double>(l.splits)) /
                                last.time);
  }
  s.noa = mean_interval(s.final_noa);
  s.encounter_rate = mean_interval(s.encounter_rates);
  s.net_merge_rate = mean_interval(s.net_merge_rates);
  s.leave = pooled_leave(arm.run);
  return s;
}

Comparison compare_arms(const ArmResult& a, const ArmResult& b) {
  Comparison c;
  c.a = summarize_arm(a);
  c.b = summarize_arm(b);
  c.noa_difference = welch_interval(c.a.final_noa, c.b.final_noa);
  c.ks_noa = ks_two_sample(c.a.final_noa, c.b.final_noa);
  c.ks_sizes = ks_two_sample(c.a.final_sizes, c.b.final_sizes);
  c.encounter_rate_difference = welch_interval(c.a.encounter_rates, c.b.encounter_rates);
  c.escape_fraction = replicate_proportion_test(c.a.escapes, c.b.escapes);
  c.net_merge_rate_difference = welch_interval(c.a.net_merge_rates, c.b.net_merge_rates);
  c.has_leaving =
      controller_rules(a.spec).leaving_happens || controller_rules(b.spec).leaving_happens;
  return c;
}

bool Comparison::sizes_judged() const {
  return ks_sizes.n_a > 0 && ks_sizes.n_b > 0;
}

bool Comparison::escape_fraction_judged() const {
  return has_leaving && escape_fraction.judged;
}

bool Comparison::noa_differs() const {
  return noa_difference.p_value < kSignificance || ks_noa.p_value < kSignificance ||
         (sizes_judged() && ks_sizes.p_value < kSignificance);
}

bool Comparison::encounter_rate_differs() const {
  return encounter_rate_difference.p_value < kSignificance;
}

bool Comparison::escape_fraction_differs() const {
  return escape_fraction_judged() && escape_fraction.p_value < kSignificance;
}

bool Comparison::net_merge_rate_differs() const {
  return net_merge_rate_difference.p_value < kSignificance;
}

bool Comparison::differs() const {
  return noa_differs() || encounter_rate_differs() || escape_fraction_differs() ||
         net_merge_rate_differs();
}

}  // namespace swarmagg
