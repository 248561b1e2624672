#include "engine/kinematic/verlet_pairs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "engine/kinematic/pair_values.hpp"

namespace swarmagg {
namespace {

using testing::candidate_values;
using testing::close_values;
using testing::uniform_positions;

// The engine's radii: s = 4, a pair reach of s plus two steps at the nominal speed, a skin
// of four such steps (kinematic_engine.cpp), and agents moving at most 0.1 per step.
constexpr SearchRadii kRadii{4.0, 4.2, true};
constexpr double kSkin = 0.8;
constexpr double kBound = 0.1;
constexpr double kBodyRadius = 1.0;  // walls keep centres within [r, L - r]

using NeighbourValue = std::tuple<AgentId, double, double, double>;

std::vector<NeighbourValue> list_of(const NeighbourLists& lists, AgentId agent) {
  std::vector<NeighbourValue> values;
  for (const Neighbour& n : lists.of(agent)) {
    values.emplace_back(n.id, n.offset.x, n.offset.y, n.distance);
  }
  return values;
}

// Every agent's list element by element (they are sorted by (distance, id), so equal lists
// are equal in order too), and the pairs as sets.
void expect_same_lists(const NeighbourLists& got, const NeighbourLists& expected,
                       const std::string& where) {
  ASSERT_EQ(got.agent_count(), expected.agent_count()) << where;
  for (AgentId a = 0; a < expected.agent_count(); ++a) {
    ASSERT_EQ(list_of(got, a), list_of(expected, a)) << where << ", agent " << a;
  }
  EXPECT_EQ(close_values(got.pairs()), close_values(expected.pairs())) << where;
}

// A VerletPairs, with its lists, checked after every call against the oracle: a fresh search
// at the same positions and radii, and lists built from it.
class CheckedVerletPairs {
 public:
  explicit CheckedVerletPairs(double skin) : verlet_(skin) {}

  // VerletPairs::find, then the checks; returns builds().
  std::uint64_t find(const ArenaGeometry& arena, std::span<const Vec2> positions,
                     const SearchRadii& radii, double moved, const std::string& where,
                     bool pairs_moved = true) {
    verlet_.find(arena, positions, radii, moved, threads_, lists_, pairs_moved);
    fresh_.find(arena, positions, radii, threads_);
    EXPECT_EQ(candidate_values(verlet_.candidates()), candidate_values(fresh_.candidates()))
        << where;
    if (radii.perception) {
      fresh_lists_.assign_from_pairs(positions.size(), fresh_.close_pairs());
      expect_same_lists(lists_, fresh_lists_, where);
    }
    return verlet_.builds();
  }

  std::span<const CandidatePair> candidates() const { return verlet_.candidates(); }
  const NeighbourLists& lists() const { return lists_; }
  VerletPairs& verlet() { return verlet_; }

 private:
  VerletPairs verlet_;
  NeighbourLists lists_;
  StepThreads threads_;
  NeighbourSearch fresh_;
  NeighbourLists fresh_lists_;
};

// Agents that wander by at most kBound per step: every fourth stands, every fourth moves by
// exactly the bound, the rest by less; a few cross the torus's seams (or run along the
// walls) at the full bound, and pairs close in head on at twice the bound, which is the
// speed the skin is sized against.
class Walkers {
 public:
  Walkers(const ArenaGeometry& arena, std::size_t n, unsigned seed)
      : arena_(arena), gen_(seed), positions_(uniform_positions(arena, n, seed)) {
    const double w = arena.width(), h = arena.height();
    for (Vec2& p : positions_) p = inside(p);
    heading_.resize(n);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
    for (Vec2& d : heading_) {
      const double a = angle(gen_);
      d = {std::cos(a), std::sin(a)};
    }
    // Straight runners across the seams (or into the walls): along x, along y, diagonally
    // through the corner; and one pair head on, starting just outside the list's window.
    positions_[1] = inside({w - 0.35, 0.5 * h});
    heading_[1] = {1.0, 0.0};
    positions_[2] = inside({0.5 * w, 0.45});
    heading_[2] = {0.0, -1.0};
    positions_[3] = inside({w - 0.55, h - 0.25});
    heading_[3] = {std::sqrt(0.5), std::sqrt(0.5)};
    positions_[5] = inside({0.25 * w, 0.25 * h});
    heading_[5] = {1.0, 0.0};
    positions_[6] = inside({0.25 * w + kRadii.pair_reach + kSkin + 0.15, 0.25 * h + 0.3});
    heading_[6] = {-1.0, 0.0};
  }

  // One step: each agent moves by at most kBound.
  void step() {
    std::uniform_real_distribution<double> fraction(0.0, 1.0), turn(-0.5, 0.5);
    for (std::size_t a = 0; a < positions_.size(); ++a) {
      double length = kBound;
      if (a >= 7 && a % 4 == 0) length = 0.0;
      if (a >= 7 && a % 4 >= 2) length = kBound * fraction(gen_);
      if (a >= 7) {
        const double t = turn(gen_);
        heading_[a] = {heading_[a].x * std::cos(t) - heading_[a].y * std::sin(t),
                       heading_[a].x * std::sin(t) + heading_[a].y * std::cos(t)};
        heading_[a] *= 1.0 / norm(heading_[a]);
      }
      positions_[a] = inside(positions_[a] + heading_[a] * length);
    }
  }

  std::span<const Vec2> positions() const { return positions_; }

 private:
  // Wrapped onto the torus; between walls, held inside (which only shortens a move).
  Vec2 inside(Vec2 p) const {
    if (arena_.torus()) return arena_.wrap(p);
    return {std::clamp(p.x, kBodyRadius, arena_.width() - kBodyRadius),
            std::clamp(p.y, kBodyRadius, arena_.height() - kBodyRadius)};
  }

  ArenaGeometry arena_;
  std::mt19937_64 gen_;
  std::vector<Vec2> positions_;
  std::vector<Vec2> heading_;
};

// Every step, the Verlet list must give exactly what a fresh search gives; and it must have
// been reused (the point of it) and rebuilt (or it could not keep up) along the way.
void expect_fresh_search_results_while_walking(const ArenaGeometry& arena, std::size_t n,
                                               unsigned seed) {
  constexpr int kSteps = 200;
  Walkers walkers(arena, n, seed);
  CheckedVerletPairs pairs(kSkin);
  std::size_t candidates_seen = 0;
  std::uint64_t builds = 0;
  for (int step = 0; step < kSteps; ++step) {
    if (step > 0) walkers.step();
    builds = pairs.find(arena, walkers.positions(), kRadii, kBound,
                        std::to_string(arena.width()) + " x " + std::to_string(arena.height()) +
                            ", step " + std::to_string(step));
    candidates_seen += pairs.candidates().size();
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(candidates_seen, static_cast<std::size_t>(kSteps)) << "too sparse to test anything";
  EXPECT_GT(builds, 1u);
  EXPECT_LT(builds, static_cast<std::uint64_t>(kSteps / 3));
}

TEST(VerletPairs, GivesTheFreshSearchPairsAndListsEveryStepOnATorus) {
  expect_fresh_search_results_while_walking(ArenaGeometry(100.0, 100.0, Topology::Torus), 600, 1);
}

TEST(VerletPairs, GivesTheFreshSearchPairsAndListsEveryStepBetweenWalls) {
  expect_fresh_search_results_while_walking(ArenaGeometry(100.0, 100.0, Topology::Walls), 600, 2);
}

// Under three strips of the reach, NeighbourSearch falls back on the pair finder: 12 x 12 for
// the fresh search and the list's alike; at 14 x 14 the fresh search uses strips (14 / 4.2)
// while the list's wider search does not (14 / 5.0).
TEST(VerletPairs, GivesTheFreshSearchPairsAndListsEveryStepInWorldsTooSmallForStrips) {
  expect_fresh_search_results_while_walking(ArenaGeometry(12.0, 12.0, Topology::Torus), 10, 3);
  expect_fresh_search_results_while_walking(ArenaGeometry(14.0, 14.0, Topology::Torus), 12, 4);
  expect_fresh_search_results_while_walking(ArenaGeometry(12.0, 12.0, Topology::Walls), 10, 5);
}

// After a build at call c, call c + k has accumulated k b of moves and reuses the list while
// reach + 2 k b + slack <= reach + skin (covers() in verlet_pairs.cpp; the slack is about
// 1e-9 of the arena's size). So a build every floor(skin / (2 b)) + 1 calls, and every
// skin / (2 b) calls when that is whole, as the slack then tips the equality. (The agents
// stand still: `moved` is only an upper bound.)
TEST(VerletPairs, RebuildsOnceTwiceTheClaimedMovesNoLongerFitInTheSkin) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Torus);
  const auto positions = uniform_positions(arena, 300, 7);
  struct Case {
    double skin;
    double moved;
    int calls_per_build;
  };
  for (const Case c : {Case{0.8, 0.1, 4}, Case{0.85, 0.1, 5}, Case{0.8, 0.2, 2}, Case{0.8, 0.4, 1},
                       Case{0.8, 0.5, 1}, Case{2.0, 0.15, 7}}) {
    CheckedVerletPairs pairs(c.skin);
    for (int call = 0; call < 30; ++call) {
      const std::string where = "skin " + std::to_string(c.skin) + ", moved " +
                                std::to_string(c.moved) + ", call " + std::to_string(call);
      ASSERT_EQ(pairs.find(arena, positions, kRadii, c.moved, where),
                static_cast<std::uint64_t>(call / c.calls_per_build + 1))
          << where;
    }
  }
}

TEST(VerletPairs, NoMovesReuseTheListForever) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Walls);
  const auto positions = uniform_positions(arena, 300, 8);
  CheckedVerletPairs pairs(kSkin);
  for (int call = 0; call < 100; ++call) {
    EXPECT_EQ(pairs.find(arena, positions, kRadii, 0.0, "call " + std::to_string(call)), 1u);
  }
}

// A reach the window still covers reuses the list; one beyond it builds anew, and the pairs
// between the old window and the new reach appear.
TEST(VerletPairs, AReachBeyondTheWindowForcesARebuild) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Torus);
  const auto positions = uniform_positions(arena, 400, 9);
  CheckedVerletPairs pairs(kSkin);
  SearchRadii radii = kRadii;
  ASSERT_EQ(pairs.find(arena, positions, radii, 0.0, "pair reach 4.2"), 1u);
  // Window 4.2 + 0.8 = 5.0: a reach of 4.6 after moves of 0.1 (4.6 + 0.2) fits.
  radii.pair_reach = 4.6;
  EXPECT_EQ(pairs.find(arena, positions, radii, 0.1, "pair reach 4.6"), 1u);
  // 5.5 does not, even without moves.
  radii.pair_reach = 5.5;
  EXPECT_EQ(pairs.find(arena, positions, radii, 0.0, "pair reach 5.5"), 2u);
  const auto beyond_old_window =
      std::count_if(pairs.candidates().begin(), pairs.candidates().end(),
                    [](const CandidatePair& p) { return norm2(p.offset) > 5.0 * 5.0; });
  EXPECT_GT(beyond_old_window, 0) << "no pair tells the rebuild from a reuse";
  // Perceiving farther than the pair reach widens the reach too: sensing 6.5 > 5.5 + 0.8.
  radii.sensing = 6.5;
  EXPECT_EQ(pairs.find(arena, positions, radii, 0.0, "sensing 6.5"), 3u);
}

// The list is by id: a different agent count lists pairs of agents that are not there, or
// misses those of the new ones.
TEST(VerletPairs, AChangedAgentCountForcesARebuild) {
  const ArenaGeometry arena(60.0, 60.0, Topology::Torus);
  auto positions = uniform_positions(arena, 200, 10);
  CheckedVerletPairs pairs(kSkin);
  ASSERT_EQ(pairs.find(arena, positions, kRadii, 0.0, "200 agents"), 1u);
  // A newcomer right beside agent 0.
  positions.push_back(arena.wrap(positions[0] + Vec2{1.5, 0.5}));
  EXPECT_EQ(pairs.find(arena, positions, kRadii, 0.0, "one agent added"), 2u);
  positions.resize(150);
  EXPECT_EQ(pairs.find(arena, positions, kRadii, 0.0, "50 agents removed"), 3u);
}

// Pairs across the seam come and go with the arena: walls to a torus joins agent 0 at x = 0.5
// with agent 1 at x = 97.5; a narrower torus (98 wide) joins it with agent 2 at x = 94.5,
// 6 apart on the 100-wide torus (beyond the window of 5) and 4 on the 98-wide one.
TEST(VerletPairs, AChangedArenaForcesARebuild) {
  const std::vector<Vec2> positions{{0.5, 50.0}, {97.5, 50.5}, {94.5, 50.0}, {50.0, 50.0}};
  const ArenaGeometry walls(100.0, 100.0, Topology::Walls), torus(100.0, 100.0, Topology::Torus),
      narrower(98.0, 100.0, Topology::Torus);
  CheckedVerletPairs pairs(kSkin);
  EXPECT_EQ(pairs.find(walls, positions, kRadii, 0.0, "walls"), 1u);
  EXPECT_EQ(pairs.candidates().size(), 1u);  // 1 and 2 only
  EXPECT_EQ(pairs.find(torus, positions, kRadii, 0.0, "torus"), 2u);
  EXPECT_EQ(pairs.candidates().size(), 2u);  // and 0 with 1 across the seam
  EXPECT_EQ(pairs.find(narrower, positions, kRadii, 0.0, "narrower torus"), 3u);
  EXPECT_EQ(pairs.candidates().size(), 3u);  // and 0 with 2
}

// Radii are inclusive in the fresh search, so the list's measure must be too: offsets of
// (3, 4) and (0, 4) are exactly 5 and 4 in floating point.
TEST(VerletPairs, PairsExactlyAtTheRadiiCountAsInAFreshSearch) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Walls);
  const std::vector<Vec2> positions{{10.0, 10.0}, {13.0, 14.0}, {10.0, 14.0}};
  CheckedVerletPairs pairs(kSkin);
  pairs.find(arena, positions, SearchRadii{4.0, 5.0, true}, 0.0, "pairs at the radii");
  EXPECT_EQ(pairs.candidates().size(), 3u);     // 0-1 at 5, 0-2 at 4, 1-2 at 3
  EXPECT_EQ(pairs.lists().pairs().size(), 2u);  // 0-2 and 1-2
}

// A packed trio (0, 1, 2) and two agents far from everybody (3, 4). While only those two
// move, and the caller says so, the pairs and lists are kept, generation and all, and still
// equal a fresh search's; a move of a paired agent, other radii or a rebuild measure again.
TEST(VerletPairs, MovesOfUnpairedAgentsKeepThePairsAndLists) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Torus);
  std::vector<Vec2> positions{{50.0, 50.0}, {52.0, 50.0}, {51.0, 51.7}, {10.0, 10.0}, {99.9, 80.0}};
  CheckedVerletPairs pairs(kSkin);
  pairs.find(arena, positions, kRadii, 0.0, "first call");
  EXPECT_FALSE(pairs.verlet().kept());
  for (const std::uint32_t agent : {0u, 1u, 2u}) EXPECT_TRUE(pairs.verlet().paired(agent));
  for (const std::uint32_t agent : {3u, 4u}) EXPECT_FALSE(pairs.verlet().paired(agent));
  const std::uint64_t generation = pairs.lists().generation();
  // Agent 4 crosses the seam: still nobody near it.
  for (int call = 0; call < 3; ++call) {
    positions[3] += Vec2{0.1, 0.0};
    positions[4] = arena.wrap(positions[4] + Vec2{0.1, 0.05});
    pairs.find(arena, positions, kRadii, 0.1, "unpaired moves, call " + std::to_string(call),
               false);
    EXPECT_TRUE(pairs.verlet().kept());
    EXPECT_EQ(pairs.lists().generation(), generation);
  }
  positions[0] += Vec2{-0.1, 0.0};
  pairs.find(arena, positions, kRadii, 0.1, "a paired agent moved", true);
  EXPECT_FALSE(pairs.verlet().kept());
  EXPECT_NE(pairs.lists().generation(), generation);
  SearchRadii wider = kRadii;
  wider.pair_reach = 4.4;
  pairs.find(arena, positions, wider, 0.0, "other radii", false);
  EXPECT_FALSE(pairs.verlet().kept());
  // Moves beyond the skin: the list is built again and measured, whatever the caller says.
  const std::uint64_t builds = pairs.verlet().builds();
  positions[3] += Vec2{0.5, 0.0};
  pairs.find(arena, positions, wider, 0.5, "rebuilt", false);
  EXPECT_EQ(pairs.verlet().builds(), builds + 1);
  EXPECT_FALSE(pairs.verlet().kept());
}

// Skin 0 (header: searched at every call): the list covers nothing beyond the reach, so it
// cannot be trusted after any call, not even one without moves (the rounding slack exceeds a
// skin of 0).
TEST(VerletPairs, WithoutASkinSearchesAtEveryCall) {
  const ArenaGeometry arena(100.0, 100.0, Topology::Torus);
  Walkers walkers(arena, 400, 11);
  CheckedVerletPairs pairs(0.0);
  for (int call = 0; call < 20; ++call) {
    const double moved = call % 2 == 0 ? kBound : 0.0;
    if (moved > 0.0) walkers.step();
    EXPECT_EQ(pairs.find(arena, walkers.positions(), kRadii, moved, "call " + std::to_string(call)),
              static_cast<std::uint64_t>(call + 1));
  }
}

// Two tasks search at once from 2 x 16384 agents on (neighbour_search.cpp); the pairs and
// lists must not depend on it, not even in order, as no output may.
TEST(VerletPairs, TwoThreadsGiveExactlyWhatOneGives) {
  const ArenaGeometry arena(740.0, 740.0, Topology::Torus);
  Walkers walkers(arena, 33000, 12);
  VerletPairs one(kSkin), two(kSkin);
  NeighbourLists lists_one, lists_two;
  StepThreads single, pair;
  pair.resize(2);
  for (int step = 0; step < 6; ++step) {
    if (step > 0) walkers.step();
    one.find(arena, walkers.positions(), kRadii, kBound, single, lists_one);
    two.find(arena, walkers.positions(), kRadii, kBound, pair, lists_two);
    const std::string where = "step " + std::to_string(step);
    ASSERT_EQ(one.candidates().size(), two.candidates().size()) << where;
    for (std::size_t k = 0; k < one.candidates().size(); ++k) {
      const CandidatePair &a = one.candidates()[k], &b = two.candidates()[k];
      ASSERT_EQ(std::tie(a.i, a.j, a.offset.x, a.offset.y),
                std::tie(b.i, b.j, b.offset.x, b.offset.y))
          << where << ", candidate " << k;
    }
    expect_same_lists(lists_two, lists_one, where);
  }
  EXPECT_EQ(one.builds(), 2u);  // steps 0 and 4
  EXPECT_EQ(two.builds(), 2u);
  EXPECT_GT(one.candidates().size(), 10000u);
}

// Without perception the lists stay as they were, and the candidates are still exact.
TEST(VerletPairs, WithoutPerceptionLeavesTheListsAsTheyAre) {
  const ArenaGeometry arena(80.0, 80.0, Topology::Torus);
  Walkers walkers(arena, 300, 13);
  CheckedVerletPairs pairs(kSkin);
  pairs.find(arena, walkers.positions(), kRadii, kBound, "step 0");
  const NeighbourLists before = pairs.lists();
  ASSERT_GT(before.total(), 0u);
  SearchRadii blind = kRadii;
  blind.perception = false;
  for (int step = 1; step < 10; ++step) {
    walkers.step();
    const std::string where = "blind step " + std::to_string(step);
    pairs.find(arena, walkers.positions(), blind, kBound, where);
    expect_same_lists(pairs.lists(), before, where);
  }
  // Perceiving again rebuilds the lists at the current positions.
  walkers.step();
  pairs.find(arena, walkers.positions(), kRadii, kBound, "perceiving again");
}

}  // namespace
}  // namespace swarmagg
