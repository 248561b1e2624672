#include "engine/kinematic/neighbour_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>
#include <vector>

#include "engine/kinematic/pair_values.hpp"

namespace swarmagg {
namespace {

using testing::candidate_values;
using testing::close_values;
using testing::PairValue;
using testing::uniform_positions;

constexpr SearchRadii kRadii{4.0, 4.2, true};

// The oracle: every pair by brute force, i < j, offset the minimum image from i to j.
struct Expected {
  std::set<PairValue> candidates;
  std::set<PairValue> close;
};
Expected brute_force(const ArenaGeometry& arena, const std::vector<Vec2>& positions,
                     const SearchRadii& radii) {
  Expected e;
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    for (std::uint32_t j = i + 1; j < positions.size(); ++j) {
      const Vec2 d = arena.displacement(positions[i], positions[j]);
      const double d2 = norm2(d);
      if (d2 <= radii.pair_reach * radii.pair_reach) e.candidates.insert({i, j, d.x, d.y, 0.0});
      if (radii.perception && d2 <= radii.sensing * radii.sensing) {
        e.close.insert({i, j, d.x, d.y, std::sqrt(d2)});
      }
    }
  }
  return e;
}

Expected found(const NeighbourSearch& search) {
  return {candidate_values(search.candidates()), close_values(search.close_pairs())};
}

// Strips (large worlds) and the pair finder (worlds under three strips high) must both
// report exactly the oracle's pairs, offsets and distances to the last bit.
TEST(NeighbourSearch, ReportsExactlyTheBruteForcePairsOnRandomWorlds) {
  NeighbourSearch search;  // reused across worlds and steps, as the engine does
  StepThreads threads;
  unsigned seed = 11;
  for (const Topology topology : {Topology::Torus, Topology::Walls}) {
    for (const auto& [width, height, n] :
         {std::tuple{120.0, 90.0, 700}, std::tuple{300.0, 11.0, 300}, std::tuple{12.0, 12.0, 20},
          std::tuple{60.0, 60.0, 1}}) {
      const ArenaGeometry arena(width, height, topology);
      for (int step = 0; step < 3; ++step) {
        const auto positions = uniform_positions(arena, static_cast<std::size_t>(n), seed++);
        for (const bool perception : {true, false}) {
          const SearchRadii radii{kRadii.sensing, kRadii.pair_reach, perception};
          search.find(arena, positions, radii, threads);
          const Expected expected = brute_force(arena, positions, radii);
          const Expected got = found(search);
          EXPECT_EQ(got.candidates, expected.candidates) << width << " x " << height;
          EXPECT_EQ(got.close, expected.close) << width << " x " << height;
        }
      }
    }
  }
}

// A pair across the seam gets the same offset as any other pair: from the lower id to the
// higher, whichever of the two the strips met first.
TEST(NeighbourSearch, OffsetsAcrossTheSeamPointFromTheLowerId) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Torus);
  const std::vector<Vec2> positions{{99.0, 50.0}, {1.0, 50.5}, {50.0, 99.5}, {50.0, 0.5}};
  NeighbourSearch search;
  StepThreads threads;
  search.find(arena, positions, kRadii, threads);
  const Expected got = found(search);
  EXPECT_EQ(got.close,
            (std::set<PairValue>{{0, 1, 2.0, 0.5, std::sqrt(4.25)}, {2, 3, 0.0, 1.0, 1.0}}));
}

TEST(NeighbourSearch, SeveralThreadsListThePairsExactlyAsOne) {
  const ArenaGeometry arena(1100.0, 1100.0, Topology::Torus);
  const auto positions = uniform_positions(arena, 60000, 5);
  NeighbourSearch one, two;
  StepThreads single, pair;
  pair.resize(2);
  one.find(arena, positions, kRadii, single);
  two.find(arena, positions, kRadii, pair);
  ASSERT_EQ(one.candidates().size(), two.candidates().size());
  ASSERT_EQ(one.close_pairs().size(), two.close_pairs().size());
  for (std::size_t k = 0; k < one.candidates().size(); ++k) {
    const CandidatePair &a = one.candidates()[k], &b = two.candidates()[k];
    ASSERT_EQ(std::tie(a.i, a.j, a.offset.x, a.offset.y),
              std::tie(b.i, b.j, b.offset.x, b.offset.y));
  }
  for (std::size_t k = 0; k < one.close_pairs().size(); ++k) {
    const ClosePair &a = one.close_pairs()[k], &b = two.close_pairs()[k];
    ASSERT_EQ(std::tie(a.i, a.j, a.offset.x, a.offset.y, a.distance),
              std::tie(b.i, b.j, b.offset.x, b.offset.y, b.distance));
  }
}

}  // namespace
}  // namespace swarmagg
