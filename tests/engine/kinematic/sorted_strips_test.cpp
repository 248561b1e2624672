#include "engine/kinematic/sorted_strips.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace swarmagg {
namespace {

using IdPair = std::pair<std::uint32_t, std::uint32_t>;

std::set<IdPair> brute_force_pairs(const ArenaGeometry& arena, const std::vector<Vec2>& positions,
                                   double window) {
  std::set<IdPair> pairs;
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    for (std::uint32_t j = i + 1; j < positions.size(); ++j) {
      if (arena.distance(positions[i], positions[j]) <= window) pairs.insert({i, j});
    }
  }
  return pairs;
}

// The candidates the strips report, by agent ids; a pair met twice fails the test. Each slot
// must also hold its agent's current position.
std::set<IdPair> strip_pairs(const SortedStrips& strips, const std::vector<Vec2>& positions) {
  std::set<IdPair> pairs;
  strips.for_each_candidate(0, strips.strips(), [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t i = strips.id(a), j = strips.id(b);
    EXPECT_EQ(strips.position(a), positions[i]);
    EXPECT_EQ(strips.position(b), positions[j]);
    const bool inserted = pairs.insert({std::min(i, j), std::max(i, j)}).second;
    EXPECT_TRUE(inserted) << "pair " << i << ", " << j << " met twice";
  });
  return pairs;
}

// Every agent takes a step of random direction and length up to `reach` (several strips
// when reach exceeds the window), wrapped on a torus or clamped inside walls.
void random_steps(const ArenaGeometry& arena, std::vector<Vec2>& positions, double reach,
                  std::mt19937_64& gen) {
  std::uniform_real_distribution<double> step(-reach, reach);
  for (Vec2& p : positions) {
    p = {p.x + step(gen), p.y + step(gen)};
    if (arena.torus()) {
      p = arena.wrap(p);
    } else {
      p = {std::clamp(p.x, 0.0, arena.width()), std::clamp(p.y, 0.0, arena.height())};
    }
  }
}

std::vector<Vec2> uniform_positions(const ArenaGeometry& arena, std::size_t n,
                                    std::mt19937_64& gen) {
  std::uniform_real_distribution<double> ux(0.0, arena.width()), uy(0.0, arena.height());
  std::vector<Vec2> positions(n);
  for (Vec2& p : positions) p = {ux(gen), uy(gen)};
  return positions;
}

struct Walk {
  Topology topology;
  double step_reach;
};

class SortedStripsWalk : public testing::TestWithParam<Walk> {};

// The update from the previous order must find exactly the pairs a brute-force search finds,
// whether agents drift within their strips or jump across several.
TEST_P(SortedStripsWalk, FindsEveryPairWithinTheWindowOnceAfterEveryUpdate) {
  const ArenaGeometry arena(70.0, 50.0, GetParam().topology);
  const double window = 4.2;
  std::mt19937_64 gen(11);
  std::vector<Vec2> positions = uniform_positions(arena, 400, gen);
  SortedStrips strips;
  StepThreads threads;
  ASSERT_TRUE(SortedStrips::fits(arena, window));
  for (int step = 0; step < 40; ++step) {
    strips.update(arena, window, positions, threads);
    EXPECT_EQ(strip_pairs(strips, positions), brute_force_pairs(arena, positions, window))
        << "step " << step;
    random_steps(arena, positions, GetParam().step_reach, gen);
  }
}

INSTANTIATE_TEST_SUITE_P(Steps, SortedStripsWalk,
                         testing::Values(Walk{Topology::Torus, 0.3}, Walk{Topology::Torus, 12.0},
                                         Walk{Topology::Walls, 0.3}, Walk{Topology::Walls, 12.0}),
                         [](const auto& info) {
                           return std::string(info.param.topology == Topology::Torus ? "torus"
                                                                                     : "walls") +
                                  (info.param.step_reach < 1.0 ? "_drift" : "_jumps");
                         });

// Each agent's search of the strip above starts where the search of the agent two before it
// ended, eight slots at a time. Here the strip above crowds 40 agents into two units of x,
// which the agents below reach, stand among and pass: the start moves by none, a few and
// more than eight slots, and a start past the first partner would lose pairs of the run.
TEST(SortedStrips, FindsThePairsOfAStripAboveThatCrowdsInOnePlace) {
  for (const Topology topology : {Topology::Torus, Topology::Walls}) {
    const ArenaGeometry arena(60.0, 60.0, topology);
    const double window = 4.2;
    std::vector<Vec2> positions;
    for (int k = 0; k < 40; ++k) positions.push_back({20.0 + 0.05 * k, 5.0 + 0.02 * (k % 7)});
    for (const double x : {1.0, 5.0, 15.9, 16.0, 18.0, 20.5, 21.0, 21.2, 24.0, 26.5, 30.0, 50.0}) {
      positions.push_back({x, 3.0});
    }
    SortedStrips strips;
    StepThreads threads;
    ASSERT_TRUE(SortedStrips::fits(arena, window));
    strips.update(arena, window, positions, threads);
    EXPECT_EQ(strip_pairs(strips, positions), brute_force_pairs(arena, positions, window));
  }
}

// Agents all crowding into one strip, then spreading out again: strips empty and fill.
TEST(SortedStrips, FollowsAgentsIntoOneStripAndOutAgain) {
  const ArenaGeometry arena(60.0, 60.0, Topology::Torus);
  const double window = 5.0;
  std::mt19937_64 gen(5);
  std::vector<Vec2> spread = uniform_positions(arena, 200, gen);
  std::vector<Vec2> crowded = spread;
  for (Vec2& p : crowded) p.y = 31.0 + p.y / 60.0;  // one strip, [30, 35)
  SortedStrips strips;
  StepThreads threads;
  for (const auto* positions : {&spread, &crowded, &spread}) {
    strips.update(arena, window, *positions, threads);
    EXPECT_EQ(strip_pairs(strips, *positions), brute_force_pairs(arena, *positions, window));
  }
}

// The passes split over threads must leave the same slots as one thread: the same pairs,
// met in the same order, after updates in which thousands of agents change strip.
TEST(SortedStrips, SeveralThreadsSortExactlyAsOne) {
  const ArenaGeometry arena(1400.0, 1400.0, Topology::Torus);
  const double window = 4.2;
  std::mt19937_64 gen(7);
  std::vector<Vec2> positions = uniform_positions(arena, 70000, gen);
  SortedStrips one, three;
  StepThreads single, pool;
  pool.resize(3);
  for (int step = 0; step < 6; ++step) {
    one.update(arena, window, positions, single);
    three.update(arena, window, positions, pool);
    std::vector<IdPair> met_by_one, met_by_three;
    auto record = [](const SortedStrips& strips, std::vector<IdPair>& met) {
      strips.for_each_candidate(0, strips.strips(), [&](std::uint32_t a, std::uint32_t b) {
        met.emplace_back(strips.id(a), strips.id(b));
      });
    };
    record(one, met_by_one);
    record(three, met_by_three);
    EXPECT_FALSE(met_by_one.empty());
    EXPECT_EQ(met_by_one, met_by_three) << "step " << step;
    random_steps(arena, positions, 3.0, gen);
  }
}

}  // namespace
}  // namespace swarmagg
