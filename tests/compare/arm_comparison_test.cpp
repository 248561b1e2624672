#include "compare/arm_comparison.hpp"

#include <gtest/gtest.h>

#include <string>

#include "compare/compare_summary.hpp"
#include "config/world_loader.hpp"

namespace swarmagg {
namespace {

// A small, dense full-model world that settles within a few hundred tu. Compaction is off:
// these fixed seeds were chosen with still-standing waiting agents, and with compaction
// seeds 11 and 12 give p = 0.02 on the NOA difference, the one false positive in twenty a
// 5 % test allows. What is tested is the comparison, not the controller.
WorldSpec small_world(double p_leave, std::uint64_t seed) {
  return load_world_text(R"(
name: small
arena: {width: 50, height: 50}
robots: {count: 30}
controller: {type: bayindir, join: true, leave: true, leave_timeout: 10,
             compaction: {enabled: false}, p_leave: )" +
                             std::to_string(p_leave) + R"(}
run: {duration: 300, replicates: 12, record_every: 50, threads: 2, seed: )" +
                             std::to_string(seed) + "}\n",
                         "small");
}

TEST(ArmComparison, AWorldAgainstItselfShowsNoSignificantDifference) {
  const ArmResult a = run_arm("first", small_world(0.005, 11));
  const ArmResult b = run_arm("second", small_world(0.005, 12));
  const Comparison c = compare_arms(a, b);
  EXPECT_GT(c.noa_difference.p_value, kSignificance);
  EXPECT_LT(c.noa_difference.low, 0.0);
  EXPECT_GT(c.noa_difference.high, 0.0);
  EXPECT_GT(c.ks_noa.p_value, kSignificance);
  EXPECT_GT(c.ks_sizes.p_value, kSignificance);
  EXPECT_FALSE(c.differs());
  EXPECT_TRUE(c.has_leaving);
  EXPECT_GT(c.a.leave.attempts.total(), 0);
  EXPECT_NE(comparison_text("small", c).find("verdict: no significant difference"),
            std::string::npos);
}

TEST(ArmComparison, NoLeavingAgainstLeavingIsDifferent) {
  const ArmResult a = run_arm("p=0", small_world(0.0, 11));
  const ArmResult b = run_arm("p=0.005", small_world(0.005, 11));
  const Comparison c = compare_arms(a, b);
  EXPECT_LT(c.noa_difference.p_value, kSignificance);
  EXPECT_LT(c.ks_sizes.p_value, kSignificance);
  EXPECT_TRUE(c.differs());
  EXPECT_EQ(c.a.leave.attempts.total(), 0);
  const nlohmann::json json = comparison_json("small", c);
  EXPECT_TRUE(json["differs"].get<bool>());
  EXPECT_EQ(json["a"]["final_noa"].size(), 12u);
}

TEST(ArmComparison, EncounterRatesArePerTimeUnit) {
  const ArmResult a = run_arm("a", small_world(0.005, 3));
  const ArmSummary s = summarize_arm(a);
  ASSERT_EQ(s.encounter_rates.size(), 12u);
  const TimeseriesRow& last = a.run.replicates[0].rows.back();
  EXPECT_DOUBLE_EQ(s.encounter_rates[0], static_cast<double>(last.events.encounters) / 300.0);
}

}  // namespace
}  // namespace swarmagg
