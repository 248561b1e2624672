#include "observers/aggregate_tracker.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "observers/observer_scene.hpp"
#include "observers/partition_tracker.hpp"

namespace swarmagg {
namespace {

using testing::Scene;

TEST(AggregateTracker, JoinsAChainAcrossTheSeamIntoOneAggregate) {
  Scene s;
  s.add(98.0, 50.0);
  s.add(1.5, 50.0);  // 3.5 from the first across the x seam
  s.add(1.5, 97.0);  // far from everyone: in no aggregate
  s.add(1.5, 53.5);  // 3.5 above the second
  s.update();
  EXPECT_EQ(s.tracker.count(), 1);
  EXPECT_EQ(s.tracker.largest(), 3);
  EXPECT_EQ(s.tracker.aggregate_of()[2], -1);  // alone: not an aggregate
  EXPECT_EQ(s.tracker.size_of_agent()[0], 3);
}

TEST(AggregateTracker, SplitsWhenTheBridgeLeaves) {
  Scene s;
  s.add(10.0, 10.0);
  s.add(10.0, 13.5);
  const auto bridge = s.add(10.0, 17.0);
  s.add(10.0, 20.5);
  s.add(10.0, 24.0);
  s.update();
  EXPECT_EQ(s.tracker.count(), 1);
  s.swarm.state[bridge] = AgentState::Leave;
  s.update();
  EXPECT_EQ(s.tracker.count(), 2);
  EXPECT_EQ(s.tracker.largest(), 2);
  EXPECT_NE(s.tracker.aggregate_of()[0], s.tracker.aggregate_of()[4]);
}

TEST(AggregateTracker, OnlyWaitingAgentsFormAggregates) {
  Scene s;
  s.add(10.0, 10.0);
  s.add(12.0, 10.0, AgentState::Go);
  s.add(14.0, 10.0, AgentState::Leave);
  s.update();
  EXPECT_EQ(s.tracker.count(), 0);
}

TEST(AggregateTracker, PartnersOnlyKeepsNearbyPairsApart) {
  Scene s;
  const auto a = s.add(10.0, 10.0);
  const auto b = s.add(13.0, 10.0);
  const auto c = s.add(16.0, 10.0);
  const auto d = s.add(19.0, 10.0);
  s.swarm.partner[a] = static_cast<std::int32_t>(b);
  s.swarm.partner[b] = static_cast<std::int32_t>(a);
  s.swarm.partner[c] = static_cast<std::int32_t>(d);
  s.swarm.partner[d] = static_cast<std::int32_t>(c);
  s.update(AggregateLinks::PartnersOnly);
  EXPECT_EQ(s.tracker.count(), 2);
  s.update(AggregateLinks::Proximity);
  EXPECT_EQ(s.tracker.count(), 1);
}

// Aggregates are numbered in order of their lowest agent, whatever order the agents stand
// in and the links come in; members_of() lists an aggregate's agents in index order.
TEST(AggregateTracker, NumbersAggregatesByTheirLowestAgentAndListsMembersInIndexOrder) {
  Scene s;
  s.add(50.0, 50.0);  // 0: aggregate 0, with 4 and 2 (a chain 0 - 4 - 2)
  s.add(10.0, 10.0);  // 1: aggregate 1, with 3
  s.add(57.0, 50.0);  // 2
  s.add(13.0, 10.0);  // 3
  s.add(53.5, 50.0);  // 4
  s.add(80.0, 80.0);  // 5: alone
  s.add(30.0, 30.0);  // 6: aggregate 2, with 7 (a pair found only after the others)
  s.add(30.0, 33.0);  // 7
  s.update();
  ASSERT_EQ(s.tracker.count(), 3);
  EXPECT_EQ(
      (std::vector<std::int32_t>(s.tracker.aggregate_of().begin(), s.tracker.aggregate_of().end())),
      (std::vector<std::int32_t>{0, 1, 0, 1, 0, -1, 2, 2}));
  EXPECT_EQ((std::vector<std::int32_t>(s.tracker.sizes().begin(), s.tracker.sizes().end())),
            (std::vector<std::int32_t>{3, 2, 2}));
  EXPECT_EQ((std::vector<std::uint32_t>(s.tracker.aggregated_agents().begin(),
                                        s.tracker.aggregated_agents().end())),
            (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 6, 7}));
  std::vector<std::uint32_t> members;
  s.tracker.members_of(2, members);
  EXPECT_EQ(members, (std::vector<std::uint32_t>{0, 2, 4}));
  s.tracker.members_of(7, members);
  EXPECT_EQ(members, (std::vector<std::uint32_t>{6, 7}));
  // The bridge leaves: its former fellows are no aggregate, the pairs keep their numbers.
  s.swarm.state[4] = AgentState::Leave;
  s.update();
  EXPECT_EQ(s.tracker.count(), 2);
  EXPECT_EQ(s.tracker.aggregate_of()[0], -1);
  EXPECT_EQ(s.tracker.aggregate_of()[1], 0);
  EXPECT_EQ(s.tracker.aggregate_of()[6], 1);
  s.tracker.members_of(3, members);
  EXPECT_EQ(members, (std::vector<std::uint32_t>{1, 3}));
}

TEST(PartitionTracker, KeysListPartsInDecreasingOrderWithFreeAgentsAsOnes) {
  const std::vector<std::int32_t> sizes{2, 3};
  EXPECT_EQ(partition_key(sizes, 7), "3+2+1+1");
  EXPECT_EQ(partition_key({}, 3), "1+1+1");
}

TEST(PartitionTracker, CountsStepsPerPartition) {
  Scene s;
  s.add(10.0, 10.0);
  s.add(13.0, 10.0);
  s.add(50.0, 50.0, AgentState::Go);
  PartitionTracker partitions;
  s.update();
  partitions.observe(s.tracker, 3);
  partitions.observe(s.tracker, 3);
  s.swarm.state[0] = AgentState::Leave;
  s.update();
  partitions.observe(s.tracker, 3);
  const auto steps = partitions.steps_by_partition();
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps.at("2+1"), 2);
  EXPECT_EQ(steps.at("1+1+1"), 1);
}

}  // namespace
}  // namespace swarmagg
