#include "bench/lib/bare_grid_loop.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace swarmagg {
namespace {

// Every pair within the radius by minimum-image distance, the slow way.
std::uint64_t pairs_by_brute_force(const BareGridLoop& loop, double radius) {
  const auto positions = loop.positions();
  std::uint64_t pairs = 0;
  for (std::size_t a = 0; a < positions.size(); ++a) {
    for (std::size_t b = a + 1; b < positions.size(); ++b) {
      pairs += norm2(loop.arena().displacement(positions[a], positions[b])) <= radius * radius;
    }
  }
  return pairs;
}

TEST(BareGridLoop, FindsEveryPairWithinTheRadiusAcrossTheSeams) {
  // Dense enough that many pairs straddle cells and the torus's edges.
  BareGridLoop loop(400, 50.0, 4.0, 1.0, 0.1, 7);
  for (int step = 0; step < 30; ++step) {
    const std::uint64_t found = loop.step();
    ASSERT_EQ(found, pairs_by_brute_force(loop, 4.0)) << "step " << step;
    ASSERT_GT(found, 0u);
  }
}

TEST(BareGridLoop, ThreeCellsASideStillCountEachPairOnce) {
  // 13 / 4 gives three cells: the cells around each are all the others.
  BareGridLoop loop(60, 13.0, 4.0, 1.0, 0.1, 3);
  for (int step = 0; step < 10; ++step) {
    const std::uint64_t found = loop.step();
    ASSERT_EQ(found, pairs_by_brute_force(loop, 4.0)) << "step " << step;
  }
}

TEST(BareGridLoop, AgentsMoveAndStayOnTheTorus) {
  BareGridLoop loop(50, 20.0, 4.0, 1.0, 0.1, 11);
  const std::vector<Vec2> before(loop.positions().begin(), loop.positions().end());
  for (int step = 0; step < 300; ++step) loop.step();
  int moved = 0;
  for (std::size_t a = 0; a < before.size(); ++a) {
    const Vec2 p = loop.positions()[a];
    EXPECT_GE(p.x, 0.0);
    EXPECT_LT(p.x, 20.0);
    EXPECT_GE(p.y, 0.0);
    EXPECT_LT(p.y, 20.0);
    moved += loop.arena().distance(before[a], p) > 0.0;
  }
  EXPECT_EQ(moved, 50);
}

}  // namespace
}  // namespace swarmagg
