#include "geometry/pair_finder.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace swarmagg {
namespace {

using PairSet = std::set<std::tuple<std::uint32_t, std::uint32_t, double, double>>;

std::vector<Vec2> random_points(const ArenaGeometry& arena, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k)
    points.push_back({arena.width() * unit(rng), arena.height() * unit(rng)});
  return points;
}

// The oracle: every pair, by brute force.
PairSet all_pairs_within(const ArenaGeometry& arena, const std::vector<Vec2>& points, double r) {
  PairSet pairs;
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    for (std::uint32_t j = i + 1; j < points.size(); ++j) {
      const Vec2 d = arena.displacement(points[i], points[j]);
      if (norm2(d) <= r * r) pairs.insert({i, j, d.x, d.y});
    }
  }
  return pairs;
}

PairSet found_pairs(PairFinder& finder, const ArenaGeometry& arena, const std::vector<Vec2>& points,
                    double r) {
  finder.reset(arena, r, points.size());
  for (const Vec2& p : points) finder.add(p);
  PairSet pairs;
  finder.for_each_pair([&](std::uint32_t i, std::uint32_t j, Vec2 d) {
    EXPECT_LT(i, j);
    EXPECT_TRUE(pairs.insert({i, j, d.x, d.y}).second) << "pair met twice: " << i << ", " << j;
  });
  return pairs;
}

TEST(PairFinder, FindsExactlyThePairsWithinTheRadiusOnRandomWorlds) {
  PairFinder finder;  // reused across worlds, as its users do
  unsigned seed = 1;
  for (const Topology topology : {Topology::Torus, Topology::Walls}) {
    for (const auto& [width, height] : {std::pair{100.0, 100.0}, std::pair{300.0, 20.0},
                                        std::pair{12.0, 12.0}, std::pair{1000.0, 1000.0}}) {
      for (const double r : {2.0, 4.0, 9.5}) {
        for (const int n : {0, 1, 40, 700}) {
          const ArenaGeometry arena(width, height, topology);
          const auto points = random_points(arena, n, seed++);
          EXPECT_EQ(found_pairs(finder, arena, points, r), all_pairs_within(arena, points, r))
              << width << " x " << height << ", r " << r << ", n " << n;
        }
      }
    }
  }
}

TEST(PairFinder, MeetsPairsAcrossTheSeamAndOnTheEdges) {
  const ArenaGeometry arena(50.0, 50.0, Topology::Torus);
  const std::vector<Vec2> points{{0.5, 25.0}, {49.5, 25.0}, {50.0, 50.0}, {0.0, 0.0}, {25.0, 25.0}};
  PairFinder finder;
  const PairSet pairs = found_pairs(finder, arena, points, 2.0);
  EXPECT_EQ(pairs, all_pairs_within(arena, points, 2.0));
  EXPECT_EQ(pairs.count({0, 1, -1.0, 0.0}), 1u);
  EXPECT_EQ(pairs.count({2, 3, 0.0, 0.0}), 1u);  // the far corner is the origin
}

TEST(PairFinder, NearQueriesSeeEveryAddedPointWithinTheRadius) {
  const ArenaGeometry arena(80.0, 60.0, Topology::Torus);
  const auto points = random_points(arena, 300, 7);
  PairFinder finder;
  finder.reset(arena, 3.0, points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec2 p = points[k];
    std::set<std::uint32_t> near;
    finder.for_each_near(p, [&](std::uint32_t q, Vec2) { near.insert(q); });
    std::set<std::uint32_t> expected;
    for (std::uint32_t q = 0; q < k; ++q) {
      if (norm2(arena.displacement(p, points[q])) <= 9.0) expected.insert(q);
    }
    EXPECT_EQ(near, expected) << k;
    finder.add(p);
  }
}

}  // namespace
}  // namespace swarmagg
