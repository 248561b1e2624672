#include "observers/union_find.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace swarmagg {
namespace {

// Unions in this order hang each element one step deeper than the last (the finds of each
// union pass through the roots only, which compresses nothing): 4 ends four steps below 0.
TEST(UnionFind, FindsTheLowestElementAsRootFromDeepInATree) {
  UnionFind sets;
  sets.reserve_elements(6);
  for (std::uint32_t a = 0; a < 6; ++a) sets.make_set(a);
  for (std::uint32_t a = 4; a-- > 0;) sets.unite(a, a + 1);
  sets.unite(4, 5);
  for (std::uint32_t a = 0; a < 6; ++a) EXPECT_EQ(sets.find(a), 0u) << a;
  EXPECT_EQ(sets.size_of_root(0), 6u);
  // The cycle through next() still holds every element once.
  std::vector<std::uint32_t> members;
  std::uint32_t a = 5;
  do {
    members.push_back(a);
    a = sets.next(a);
  } while (a != 5);
  std::sort(members.begin(), members.end());
  EXPECT_EQ(members, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

// After the finds, settle() in increasing order reaches each root in one step.
TEST(UnionFind, SettlesEveryElementInIncreasingOrder) {
  UnionFind sets;
  sets.reserve_elements(9);
  for (std::uint32_t a = 0; a < 9; ++a) sets.make_set(a);
  const std::vector<std::pair<std::uint32_t, std::uint32_t>> links = {
      {7, 8}, {6, 7}, {5, 6}, {1, 5}, {2, 3}, {3, 4}, {0, 2}, {4, 8}};
  for (const auto& [a, b] : links) sets.unite(a, b);
  for (std::uint32_t a = 0; a < 9; ++a) EXPECT_EQ(sets.settle(a), 0u) << a;
  EXPECT_EQ(sets.size_of_root(0), 9u);
}

TEST(UnionFind, UnitingTwiceChangesNothing) {
  UnionFind sets;
  sets.reserve_elements(4);
  for (std::uint32_t a = 0; a < 4; ++a) sets.make_set(a);
  sets.unite(2, 3);
  sets.unite(3, 2);
  EXPECT_EQ(sets.find(3), 2u);
  EXPECT_EQ(sets.size_of_root(2), 2u);
  EXPECT_EQ(sets.next(sets.next(2)), 2u);
  EXPECT_EQ(sets.find(0), 0u);
  EXPECT_EQ(sets.size_of_root(0), 1u);
}

}  // namespace
}  // namespace swarmagg
