#include "control_interface/neighbour_lists.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace swarmagg {
namespace {

std::vector<AgentId> ids_of(const NeighbourLists& lists, AgentId agent) {
  std::vector<AgentId> ids;
  for (const Neighbour& nb : lists.of(agent)) ids.push_back(nb.id);
  return ids;
}

// Lists of two are ordered without a branch, longer ones by insertion: each comes out
// nearest first, equal distances by id, whatever order the pairs came in.
TEST(NeighbourLists, OrdersEveryListNearestFirstAndTiesById) {
  const std::vector<ClosePair> pairs = {
      {0, 1, {3, 0}, 3.0},  {0, 2, {2, 0}, 2.0},                       // agent 0: two
      {3, 6, {1, 0}, 1.5},  {3, 4, {1, 0}, 1.5}, {3, 5, {1, 0}, 1.0},  // agent 3: three, a tie
      {7, 8, {4, 0}, 4.0},  {7, 9, {1, 0}, 1.0}, {7, 10, {3, 0}, 3.0},
      {7, 11, {2, 0}, 2.0},  // agent 7: four
  };
  NeighbourLists lists;
  lists.assign_from_pairs(12, pairs);
  EXPECT_EQ(ids_of(lists, 0), (std::vector<AgentId>{2, 1}));
  EXPECT_EQ(ids_of(lists, 3), (std::vector<AgentId>{5, 4, 6}));
  EXPECT_EQ(ids_of(lists, 7), (std::vector<AgentId>{9, 11, 10, 8}));
  EXPECT_EQ(ids_of(lists, 1), (std::vector<AgentId>{0}));
  EXPECT_EQ(lists.of(1)[0].offset.x, -3.0);  // seen from the other end
  EXPECT_EQ(ids_of(lists, 11), (std::vector<AgentId>{7}));
}

TEST(NeighbourLists, KeepsEveryPairOnceWhicheverWayTheyAreFilled) {
  NeighbourLists assigned;
  assigned.assign_from_pairs(3, std::vector<ClosePair>{{0, 1, {1, 0}, 1.0}, {1, 2, {2, 0}, 2.0}});
  ASSERT_EQ(assigned.pairs().size(), 2u);
  EXPECT_EQ(assigned.pairs()[1].j, 2u);

  // Agent by agent (as the Box2D engine fills them): the pairs are those with id > agent.
  NeighbourLists pushed;
  pushed.reset(3);
  pushed.push({1, {1, 0}, 1.0});
  pushed.close_agent(0);
  pushed.push({2, {2, 0}, 2.0});
  pushed.push({0, {-1, 0}, 1.0});
  pushed.close_agent(1);
  pushed.push({1, {-2, 0}, 2.0});
  pushed.close_agent(2);
  ASSERT_EQ(pushed.pairs().size(), 2u);
  EXPECT_EQ(pushed.pairs()[0].i, 0u);
  EXPECT_EQ(pushed.pairs()[0].j, 1u);
  EXPECT_EQ(pushed.pairs()[1].i, 1u);
  EXPECT_EQ(pushed.pairs()[1].j, 2u);
  EXPECT_EQ(pushed.pairs()[1].distance, 2.0);
  pushed.reset(3);
  EXPECT_TRUE(pushed.pairs().empty());
}

// Whatever was computed from the lists may be kept while their generation stays: it stays
// exactly while the pairs repeat, bit for bit and in order.
TEST(NeighbourLists, TheSamePairsKeepTheGenerationAndOthersChangeIt) {
  const std::vector<ClosePair> pairs = {{0, 1, {1, 0}, 1.0}, {1, 2, {2, 0}, 2.0}};
  NeighbourLists lists;
  lists.assign_from_pairs(3, pairs);
  const std::uint64_t first = lists.generation();
  lists.assign_from_pairs(3, pairs);
  EXPECT_EQ(lists.generation(), first);
  EXPECT_EQ(ids_of(lists, 1), (std::vector<AgentId>{0, 2}));

  std::vector<ClosePair> moved = pairs;
  moved[1].offset.x = std::nextafter(2.0, 3.0);  // one bit further
  lists.assign_from_pairs(3, moved);
  EXPECT_NE(lists.generation(), first);
  EXPECT_EQ(lists.of(1)[1].offset.x, moved[1].offset.x);

  const std::uint64_t second = lists.generation();
  lists.assign_from_pairs(4, moved);  // one more agent, no pair of its own
  EXPECT_NE(lists.generation(), second);
  EXPECT_TRUE(lists.of(3).empty());

  const std::uint64_t third = lists.generation();
  lists.reset(4);
  EXPECT_NE(lists.generation(), third);
  lists.assign_from_pairs(4, moved);  // after a reset, the same pairs are lists again
  EXPECT_EQ(lists.of(1).size(), 2u);
}

// The same pairs measured anew (a few agents moved, no pair came or went) are written into the
// lists in place; the lists must be exactly those a rebuild from the new pairs makes, however
// far the new distances reorder them (ties included), and the generation must change.
TEST(NeighbourLists, PairsMeasuredAnewGiveTheListsARebuildGives) {
  std::mt19937_64 gen(42);
  std::uniform_int_distribution<int> few(0, 3);
  constexpr AgentId kAgents = 12;
  std::vector<ClosePair> pairs;
  for (AgentId i = 0; i < kAgents; ++i) {
    for (AgentId j = i + 1; j < kAgents; ++j) {
      if ((i * 7 + j * 3) % 4 != 0) pairs.push_back({i, j, {double(j - i), 0.5}, double(j - i)});
    }
  }
  NeighbourLists lists;
  lists.assign_from_pairs(kAgents, pairs);
  for (int round = 0; round < 200; ++round) {
    const AgentId moved = static_cast<AgentId>(gen() % kAgents);
    for (ClosePair& p : pairs) {
      if (p.i != moved && p.j != moved) continue;
      p.distance = 1.0 + few(gen);  // small integers: many ties, broken by id
      p.offset = {p.distance, static_cast<double>(round)};
    }
    const std::uint64_t before = lists.generation();
    lists.assign_from_pairs(kAgents, pairs);
    EXPECT_NE(lists.generation(), before);
    NeighbourLists rebuilt;
    rebuilt.assign_from_pairs(kAgents, pairs);
    for (AgentId a = 0; a < kAgents; ++a) {
      const auto got = lists.of(a), want = rebuilt.of(a);
      ASSERT_EQ(got.size(), want.size());
      for (std::size_t k = 0; k < got.size(); ++k) {
        ASSERT_EQ(got[k].id, want[k].id) << "round " << round << " agent " << a;
        ASSERT_EQ(got[k].distance, want[k].distance);
        ASSERT_EQ(got[k].offset, want[k].offset);
      }
    }
    ASSERT_EQ(lists.pairs().size(), pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      ASSERT_EQ(lists.pairs()[k].distance, pairs[k].distance);
    }
  }
}

}  // namespace
}  // namespace swarmagg
