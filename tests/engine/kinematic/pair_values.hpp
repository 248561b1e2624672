#pragma once
// Found pairs as sets of exact values, so that two searches compare to the last bit whatever
// order they list their pairs in; and uniform random agents to search. Shared by the tests of
// NeighbourSearch and VerletPairs.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <span>
#include <tuple>
#include <vector>

#include "control_interface/neighbour_lists.hpp"
#include "engine/kinematic/guarded_motion.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg::testing {

// A pair as a value: ids, offset and (for close pairs) distance, compared exactly.
using PairValue = std::tuple<std::uint32_t, std::uint32_t, double, double, double>;

inline std::vector<Vec2> uniform_positions(const ArenaGeometry& arena, std::size_t n,
                                           unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> ux(0.0, arena.width()), uy(0.0, arena.height());
  std::vector<Vec2> positions(n);
  for (Vec2& p : positions) p = {ux(gen), uy(gen)};
  return positions;
}

// Each pair must come once, as i < j.
inline std::set<PairValue> candidate_values(std::span<const CandidatePair> pairs) {
  std::set<PairValue> values;
  for (const CandidatePair& p : pairs) {
    EXPECT_LT(p.i, p.j);
    EXPECT_TRUE(values.insert({p.i, p.j, p.offset.x, p.offset.y, 0.0}).second)
        << "candidate " << p.i << ", " << p.j << " listed twice";
  }
  return values;
}

inline std::set<PairValue> close_values(std::span<const ClosePair> pairs) {
  std::set<PairValue> values;
  for (const ClosePair& p : pairs) {
    EXPECT_LT(p.i, p.j);
    EXPECT_TRUE(values.insert({p.i, p.j, p.offset.x, p.offset.y, p.distance}).second)
        << "close pair " << p.i << ", " << p.j << " listed twice";
  }
  return values;
}

}  // namespace swarmagg::testing
