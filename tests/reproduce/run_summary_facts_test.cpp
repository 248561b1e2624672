#include "reproduce/run_summary_facts.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "output/scratch_folder.hpp"

namespace swarmagg {
namespace {

RunSummaryFacts facts_of(const std::string& summary) {
  const ScratchFolder folder("summary-facts");
  std::ofstream(folder.path() / "summary.json") << summary;
  return run_summary_facts(folder.path());
}

TEST(RunSummaryFacts, ReadsTheSpacingAndWhereAttemptsStart) {
  const RunSummaryFacts facts = facts_of(
      R"({"pooled": {"final": {"mean_member_spacing": 2.5},
                     "leave_attempts": {"inside": 3, "rim": 97, "total": 100}}})");
  EXPECT_EQ(facts.member_spacing, 2.5);
  EXPECT_EQ(facts.inside_attempt_share, 0.03);
}

// A summary without those facts, damaged, or of another tool's types gives none, no error.
TEST(RunSummaryFacts, WhatIsNotANumberIsNoFact) {
  for (const char* summary :
       {R"({"pooled": {"leave_attempts": {"inside": 0, "total": 0}}})", R"({"pooled": 3})",
        R"({"pooled": {"final": [1], "leave_attempts": {"inside": "3", "total": 100}}})",
        R"([1, 2])", "{damaged", ""}) {
    const RunSummaryFacts facts = facts_of(summary);
    EXPECT_FALSE(facts.member_spacing) << summary;
    EXPECT_FALSE(facts.inside_attempt_share) << summary;
  }
}

}  // namespace
}  // namespace swarmagg
