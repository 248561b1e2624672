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
WorldSpec small_world(double p_leave, std::uint64_t seed, int agents = 30, int replicates = 12) {
  // Appended to a string, not R"(...)" + std::to_string(agents): see the precompiled header
  // in tests/CMakeLists.txt.
  std::string text = R"(
name: small
arena: {width: 50, height: 50}
robots: {count: )";
  text += std::to_string(agents);
  text += R"(}
controller: {type: bayindir, join: true, leave: true, leave_timeout: 10,
             compaction: {enabled: false}, p_leave: )";
  text += std::to_string(p_leave);
  text += R"(}
run: {duration: 300, record_every: 50, threads: 2, replicates: )";
  text += std::to_string(replicates);
  text += ", seed: ";
  text += std::to_string(seed);
  text += "}\n";
  return load_world_text(text, "small");
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
  const std::string text = comparison_text("small", c);
  for (const char* verdict :
       {"  final NOA: no significant difference", "  encounter rate: no significant difference",
        "  escape fraction: no significant difference"}) {
    EXPECT_NE(text.find(verdict), std::string::npos) << verdict << "\n" << text;
  }
}

// The final sizes' KS test is the weakest of the three: with 12 replicates an arm its p
// ranged over 4e-6 .. 0.099 across seeds 1-12; with 24, over 2e-9 .. 0.002.
TEST(ArmComparison, NoLeavingAgainstLeavingIsDifferent) {
  const ArmResult a = run_arm("p=0", small_world(0.0, 11, 30, 24));
  const ArmResult b = run_arm("p=0.005", small_world(0.005, 11, 30, 24));
  const Comparison c = compare_arms(a, b);
  EXPECT_LT(c.noa_difference.p_value, kSignificance);
  EXPECT_LT(c.ks_sizes.p_value, kSignificance);
  EXPECT_TRUE(c.differs());
  EXPECT_EQ(c.a.leave.attempts.total(), 0);
  const nlohmann::json json = comparison_json("small", c);
  EXPECT_TRUE(json["differs"].get<bool>());
  EXPECT_EQ(json["a"]["final_noa"].size(), 24u);
}

// Each verdict names its quantity: a denser arm meets more often (encounter rate differs),
// and a world without leaving leaves the escape fraction unjudged.
TEST(ArmComparison, EveryQuantityGetsItsOwnVerdict) {
  const ArmResult sparse = run_arm("sparse", small_world(0.0, 11, 15));
  const ArmResult dense = run_arm("dense", small_world(0.0, 11, 60));
  const Comparison c = compare_arms(sparse, dense);
  EXPECT_TRUE(c.encounter_rate_differs());
  EXPECT_FALSE(c.has_leaving);
  EXPECT_FALSE(c.escape_fraction_differs());
  const std::string text = comparison_text("small", c);
  EXPECT_NE(text.find("  encounter rate: different (Welch)"), std::string::npos) << text;
  EXPECT_NE(text.find("  escape fraction: not judged"), std::string::npos) << text;
  EXPECT_NE(text.find("  final NOA: "), std::string::npos) << text;
  const nlohmann::json json = comparison_json("small", c);
  EXPECT_EQ(json["verdicts"]["encounter_rate"], "different");
  EXPECT_EQ(json["verdicts"]["escape_fraction"], "not judged");
  EXPECT_TRUE(json["a"]["leave_attempts"]["rim_fraction_out"].is_null());  // nobody leaves
}

// Arm a: 10/20 and 20/30 (pooled 0.6; residuals -2 and 2), variance 2/1 * 8 / 50^2 = 0.0064;
// arm b: 15/20 and 24/30 (pooled 0.78; residuals -0.6 and 0.6), 2/1 * 0.72 / 50^2 = 0.000576.
// t = 0.18 / sqrt(0.006976) = 2.15511, Welch-Satterthwaite dof 0.006976^2 / (0.0064^2 +
// 0.000576^2) = 1.17855, p = 0.245506 (scipy.stats.t.sf). The pooled z test said 0.0046.
TEST(ArmComparison, EscapeFractionsAreComparedOnTheReplicatesSpread) {
  const ProportionResult r = replicate_proportion_test({{10, 20}, {20, 30}}, {{15, 20}, {24, 30}});
  EXPECT_DOUBLE_EQ(r.fraction_a, 0.6);
  EXPECT_DOUBLE_EQ(r.fraction_b, 0.78);
  EXPECT_NEAR(r.t, 2.1551091417, 1e-9);
  EXPECT_NEAR(r.dof, 1.1785537149, 1e-9);
  EXPECT_NEAR(r.p_value, 0.2455061514, 1e-8);
  // Replicates without attempts say nothing of the fraction: padding changes nothing.
  const ProportionResult padded =
      replicate_proportion_test({{10, 20}, {0, 0}, {20, 30}, {0, 0}}, {{15, 20}, {24, 30}, {0, 0}});
  EXPECT_DOUBLE_EQ(padded.p_value, r.p_value);
  EXPECT_DOUBLE_EQ(padded.dof, r.dof);
  // Fewer than two replicates with attempts in an arm: not judged.
  EXPECT_FALSE(replicate_proportion_test({{0, 0}, {0, 0}}, {{5, 10}, {4, 10}}).judged);
  EXPECT_FALSE(replicate_proportion_test({{5, 10}, {0, 0}, {0, 0}}, {{8, 10}, {7, 10}}).judged);
  // No replicate strays from its arm's fraction: the binomial variance of the pooled z test.
  // 1/1 and 1/1 against 0/1 and 0/1: pooled 0.5, z = -1 / sqrt(0.25 (1/2 + 1/2)) = -2,
  // p = 0.0455 (it said p = 0, certain, from four attempts).
  const ProportionResult still = replicate_proportion_test({{1, 1}, {1, 1}}, {{0, 1}, {0, 1}});
  EXPECT_TRUE(still.judged);
  EXPECT_NEAR(still.t, -2.0, 1e-12);
  EXPECT_NEAR(still.p_value, 0.0455003, 1e-6);
  EXPECT_EQ(replicate_proportion_test({{5, 10}, {5, 10}}, {{5, 10}, {10, 20}}).p_value, 1.0);
  EXPECT_EQ(replicate_proportion_test({{10, 10}, {5, 5}}, {{3, 3}, {4, 4}}).p_value, 1.0);
}

TEST(ArmComparison, EncounterRatesArePerTimeUnit) {
  const ArmResult a = run_arm("a", small_world(0.005, 3));
  const ArmSummary s = summarize_arm(a);
  ASSERT_EQ(s.encounter_rates.size(), 12u);
  const TimeseriesRow& last = a.run.replicates[0].rows.back();
  EXPECT_DOUBLE_EQ(s.encounter_rates[0], static_cast<double>(last.events.encounters) / 300.0);
}

// Every replicate's lineage, followed after every step, accounts for its final NOA; the net
// merges are per tu; the text and JSON report them with their own verdict.
TEST(ArmComparison, LineageAccountsForEachReplicatesFinalNoa) {
  const ArmResult a = run_arm("a", small_world(0.005, 3));
  const ArmSummary s = summarize_arm(a);
  ASSERT_EQ(s.lineage.size(), 12u);
  ASSERT_EQ(s.net_merge_rates.size(), 12u);
  std::uint64_t merges = 0;
  for (std::size_t k = 0; k < s.lineage.size(); ++k) {
    const LineageCounts& l = s.lineage[k];
    EXPECT_EQ(static_cast<double>(l.births) - static_cast<double>(l.deaths) -
                  static_cast<double>(l.merges) + static_cast<double>(l.splits),
              s.final_noa[k])
        << "replicate " << k;
    EXPECT_DOUBLE_EQ(s.net_merge_rates[k],
                     (static_cast<double>(l.merges) - static_cast<double>(l.splits)) / 300.0);
    merges += l.merges;
  }
  EXPECT_GT(merges, 0u);  // a dense world with joining: searchers bridge aggregates
  const Comparison c = compare_arms(a, run_arm("b", small_world(0.005, 4)));
  const std::string text = comparison_text("small", c);
  EXPECT_NE(text.find("net merges (merges - splits) per tu: a "), std::string::npos) << text;
  EXPECT_NE(text.find("  net merge rate: "), std::string::npos) << text;
  const nlohmann::json json = comparison_json("small", c);
  EXPECT_EQ(json["a"]["lineage"]["merges"].size(), 12u);
  EXPECT_TRUE(json["verdicts"].contains("net_merge_rate"));
  EXPECT_TRUE(json["net_merge_rate_difference"].contains("p_value"));
}

// Undefined statistics are not judged: KS against an empty sample of final sizes (one arm
// ended with no aggregate), an escape fraction of 0 attempts. They used to read "D = 0, p = 1:
// no significant difference" and "0.000 (p = 1)".
TEST(ArmComparison, UndefinedStatisticsAreNotJudged) {
  Comparison c;
  c.a.label = "kinematic";
  c.b.label = "box2d";
  c.noa_difference.p_value = 1.0;
  c.ks_noa.p_value = 1.0;
  c.ks_sizes = {0.0, 1.0, 6, 0};
  c.encounter_rate_difference.p_value = 1.0;
  c.net_merge_rate_difference.p_value = 1.0;
  c.escape_fraction.p_value = 1.0;
  c.has_leaving = true;
  c.a.leave.attempts.rim = 3;  // the other arm made none
  EXPECT_FALSE(c.sizes_judged());
  EXPECT_FALSE(c.escape_fraction_judged());
  const std::string text = comparison_text("small", c);
  EXPECT_NE(text.find("KS final aggregate sizes (6 vs 0 aggregates): not judged (an arm ended "
                      "with no aggregate)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  escape fraction: not judged (an arm has fewer than two replicates with "
                      "LEAVE attempts)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("kinematic: rim 0/3 got out (0.000), inside 0/0 (-)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("  final NOA: no significant difference (Welch on the mean, KS on NOA)\n"),
            std::string::npos)
      << text;
  // A significant p of an undefined test decides nothing.
  c.ks_sizes.p_value = 0.0;
  c.escape_fraction.p_value = 0.0;
  EXPECT_FALSE(c.differs());
  const nlohmann::json json = comparison_json("small", c);
  EXPECT_FALSE(json["ks_final_aggregate_sizes_judged"].get<bool>());
  EXPECT_FALSE(json["escape_fraction"]["judged"].get<bool>());
  EXPECT_EQ(json["verdicts"]["escape_fraction"], "not judged");
  EXPECT_TRUE(json["a"]["leave_attempts"]["inside_fraction_out"].is_null());
  EXPECT_EQ(json["a"]["leave_attempts"]["rim_fraction_out"], 0.0);
}

}  // namespace
}  // namespace swarmagg
