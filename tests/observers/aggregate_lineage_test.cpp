#include "observers/aggregate_lineage.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
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

TEST(AggregateLineage, TwoAggregatesSwappingMembersAreTwoMergesAndTwoSplits) {
  AggregateLineage lineage;
  observe(lineage, {0, 0, 1, 1});
  observe(lineage, {0, 1, 0, 1});  // each aggregate now holds a member of both before
  EXPECT_EQ(counts(lineage), (Counts{2, 0, 2, 2}));
}

// The counts by another route: per aggregate, the set of aggregates it shares members with.
Counts reference_step(const std::vector<std::int32_t>& before, int count_before,
                      const std::vector<std::int32_t>& now, int count_now) {
  std::vector<std::set<std::int32_t>> sources(count_now), successors(count_before);
  for (std::size_t a = 0; a < now.size(); ++a) {
    if (now[a] < 0 || before[a] < 0) continue;
    sources[now[a]].insert(before[a]);
    successors[before[a]].insert(now[a]);
  }
  Counts c{0, 0, 0, 0};
  for (const auto& from : sources) {
    if (from.empty())
      ++c[0];
    else
      c[2] += from.size() - 1;
  }
  for (const auto& to : successors) {
    if (to.empty())
      ++c[1];
    else
      c[3] += to.size() - 1;
  }
  return c;
}

// Random partitions, numbered by their lowest member as the tracker numbers aggregates.
std::vector<std::int32_t> random_labels(std::mt19937& random, int agents) {
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
  return labels;
}

TEST(AggregateLineage, CountsWhatEachAggregatesSourcesAndSuccessorsSay) {
  std::mt19937 random(7);
  AggregateLineage lineage;
  std::vector<std::int32_t> before(40, -1);
  Counts expected{0, 0, 0, 0};
  for (int step = 0; step < 2000; ++step) {
    // Three steps in four keep the last labels but for one agent dropped, so that most steps
    // change little, as in a simulation.
    std::vector<std::int32_t> now = random_labels(random, 40);
    if (step % 4 != 0) {
      now = before;
      now[random() % 40] = -1;
    }
    const Counts step_counts = reference_step(before, count_of(before), now, count_of(now));
    for (std::size_t k = 0; k < 4; ++k) expected[k] += step_counts[k];
    observe(lineage, now);
    ASSERT_EQ(counts(lineage), expected) << "step " << step;
    before = now;
  }
  EXPECT_GT(expected[2], 0u);
  EXPECT_GT(expected[3], 0u);
}

}  // namespace
}  // namespace swarmagg
