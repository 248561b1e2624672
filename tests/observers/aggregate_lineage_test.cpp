#include "observers/aggregate_lineage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

namespace swarmagg {
namespace {

// Labels as the tracker gives them: aggregates numbered in order of their lowest member.
int count_of(const std::vector<std::int32_t>& labels) {
  return labels.empty() ? 0 : std::max(*std::max_element(labels.begin(), labels.end()) + 1, 0);
}

void observe(AggregateLineage& lineage, const std::vector<std::int32_t>& labels) {
  lineage.observe(labels, count_of(labels));
}

// Births, deaths, merges and splits so far.
std::array<std::uint64_t, 4> counts(const AggregateLineage& lineage) {
  const LineageCounts& c = lineage.counts();
  return {c.births, c.deaths, c.merges, c.splits};
}
using Counts = std::array<std::uint64_t, 4>;

TEST(AggregateLineage, FirstAggregatesAreBirths) {
  AggregateLineage lineage;
  observe(lineage, {-1, -1, -1, -1, -1});
  observe(lineage, {0, 0, -1, 1, 1});
  EXPECT_EQ(counts(lineage), (Counts{2, 0, 0, 0}));
}

TEST(AggregateLineage, TwoAggregatesJoinedByABridgeAreOneMerge) {
  AggregateLineage lineage;
  observe(lineage, {0, 0, -1, 1, 1});
  observe(lineage, {0, 0, 0, 0, 0});  // agent 2 joined both
  EXPECT_EQ(counts(lineage), (Counts{2, 0, 1, 0}));
}

TEST(AggregateLineage, AnAggregateBrokenInTwoIsOneSplit) {
  AggregateLineage lineage;
  observe(lineage, {0, 0, 0, 0, 0});
  observe(lineage, {0, 0, -1, 1, 1});  // the middle member left
  EXPECT_EQ(counts(lineage), (Counts{1, 0, 0, 1}));
}

TEST(AggregateLineage, AnAggregateLeftByAllButOneDiesAndANewPairIsBorn) {
  AggregateLineage lineage;
  observe(lineage, {0, 0, -1, -1});
  observe(lineage, {-1, -1, 0, 0});
  EXPECT_EQ(counts(lineage), (Counts{2, 1, 0, 0}));
}

TEST(AggregateLineage, NewLabelsForTheSameAggregatesChangeNothing) {
  AggregateLineage lineage;
  observe(lineage, {-1, 0, 0, 1, 1});
  // Agent 0 joins the second aggregate, which renumbers both: the same aggregates, one grown.
  observe(lineage, {0, 1, 1, 0, 0});
  EXPECT_EQ(counts(lineage), (Counts{2, 0, 0, 0}));
}

// Over any sequence of labellings the counts account for the NOA exactly.
TEST(AggregateLineage, CountsAccountForEveryChangeOfTheNoa) {
  std::mt19937 random(7);
  AggregateLineage lineage;
  const int agents = 40;
  int noa = 0;
  for (int step = 0; step < 500; ++step) {
    // A random partition: each agent in one of a few groups or none, groups of one dropped,
    // numbered by their lowest member as the tracker does.
    std::vector<int> group(agents);
    const int groups = 1 + static_cast<int>(random() % 8);
    for (int& g : group) g = static_cast<int>(random() % (groups + 3)) - 3;
    std::vector<int> size(groups, 0);
    for (const int g : group) size[std::max(g, 0)] += g >= 0;
    std::vector<std::int32_t> labels(agents, -1);
    std::vector<int> number(groups, -1);
    int count = 0;
    for (int a = 0; a < agents; ++a) {
      const int g = group[a];
      if (g < 0 || size[g] < 2) continue;
      if (number[g] < 0) number[g] = count++;
      labels[a] = number[g];
    }
    lineage.observe(labels, count);
    noa = count;
    const LineageCounts& c = lineage.counts();
    ASSERT_EQ(static_cast<std::int64_t>(c.births) - static_cast<std::int64_t>(c.deaths) -
                  static_cast<std::int64_t>(c.merges) + static_cast<std::int64_t>(c.splits),
              noa)
        << "step " << step;
  }
  EXPECT_GT(lineage.counts().merges, 0u);
  EXPECT_GT(lineage.counts().splits, 0u);
}

}  // namespace
}  // namespace swarmagg
