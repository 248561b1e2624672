#include "reproduce/compaction_report.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "analysis/variant_error.hpp"

namespace swarmagg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

CompactionEffect bayindir(const std::string& world, OnOff original, OnOff escape_fraction,
                          OnOff growth) {
  CompactionEffect e;
  e.figures = "18";
  e.world = world;
  e.variants = {"original", "collision", kMeasuredVariant};
  e.errors = {original, {1.0, 1.0}, {0.5, 0.6}};
  e.final_noa = {20.0, 25.0};
  e.member_spacing = {2.0, 3.9};
  e.growth_vs_model = growth;
  e.escape_fraction = escape_fraction;
  return e;
}

TEST(CompactionReport, TableRowHoldsEachVariantOnAndOff) {
  const std::string text = compaction_section(
      {bayindir("full", {6.0, 2.5}, {0.7, 0.98}, {1.7, 1.4})}, {}, {}, "compaction-off");
  EXPECT_NE(text.find("| 18 | full | NOA RMSE | 6 | 2.5 | 1 | 1 | 0.5 | 0.6 |"), std::string::npos)
      << text;
  EXPECT_NE(text.find("| 18 | full | 20 | 25 | 2 | 3.9 | 1.7 | 1.4 | 0.7 | 0.98 |"),
            std::string::npos)
      << text;
}

TEST(CompactionReport, ParagraphFollowsTheNumbers) {
  const std::vector<CompactionEffect> effects{
      bayindir("growing", {1.9, 2.7}, {kNaN, kNaN}, {1.2, 1.5}),
      bayindir("full", {6.0, 2.5}, {0.7, 0.98}, {1.7, 1.4}),
      bayindir("creation", {0.4, 0.4}, {kNaN, kNaN}, {kNaN, kNaN})};
  const std::string text = compaction_section(effects, {}, {}, "compaction-off");
  // Growth is judged only where nobody leaves (growing), and is slower there.
  EXPECT_NE(text.find("growth is faster in 0, slower in 1 of 1 such worlds"), std::string::npos)
      << text;
  EXPECT_NE(text.find("more in 0, fewer in 1 of 1 worlds that leave"), std::string::npos) << text;
  EXPECT_NE(text.find("original larger in 1, smaller in 1 and unchanged in 1 (creation) of 3"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("moved most in full (2.5 off, 6 on), where 0.7 of the LEAVE attempts"),
            std::string::npos)
      << text;
}

// The paragraph gives where the attempts start (inside or on the rim), not a mechanism the
// numbers do not show ("a leaver enclosed by its aggregate is blocked").
TEST(CompactionReport, SaysWhereTheFailedAttemptsStart) {
  CompactionEffect full = bayindir("full", {6.0, 2.5}, {0.2, 0.98}, {1.7, 1.4});
  full.inside_attempt_share = {0.003, 0.01};
  const std::string text = compaction_section({full}, {}, {}, "compaction-off");
  EXPECT_NE(text.find("With compaction on, 0.003 of the attempts start inside an aggregate"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("blocked by the bodies"), std::string::npos) << text;
}

TEST(CompactionReport, ListsTheClaimsWhoseVerdictFlips) {
  const std::vector<ClaimCheck> on{{"Fig 18", "original better", "not supported", "on numbers"},
                                   {"Fig 7", "overlap", "supported", "x"}};
  const std::vector<ClaimCheck> off{{"Fig 18", "original better", "supported", "off numbers"},
                                    {"Fig 7", "overlap", "supported", "x"}};
  const std::string text = compaction_section(
      {bayindir("full", {6.0, 2.5}, {0.7, 0.98}, {1.7, 1.4})}, on, off, "compaction-off");
  EXPECT_NE(text.find("- **Fig 18** original better: **not supported** with compaction on, "
                      "**supported** off. Off: off numbers"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("**Fig 7**"), std::string::npos);
  const std::string same = compaction_section(
      {bayindir("full", {6.0, 2.5}, {0.7, 0.98}, {1.7, 1.4})}, on, on, "compaction-off");
  EXPECT_NE(same.find("No claim of the paper changes its verdict"), std::string::npos);
}

TEST(CompactionReport, SaysSoWhenNothingWasCompared) {
  EXPECT_NE(compaction_section({}, {}, {}, "compaction-off").find("nothing was compared"),
            std::string::npos);
}

}  // namespace
}  // namespace swarmagg
