#include "engine/kinematic/guarded_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <span>
#include <vector>

namespace swarmagg {
namespace {

constexpr Signal kGo = 0;
constexpr Signal kWait = 1;
// s = 4, 2r = 2, dt = 1, sliding at contacts, no walls.
constexpr MotionLimits kLimits{4.0, 2.0, 1.0, ContactResponse::Slide, false, {}};

MotionCommand moving(Vec2 velocity, SignalMask halt_on = 0, SignalMask blocked_by = 0) {
  return MotionCommand{velocity, halt_on, blocked_by, 0};
}

TEST(GuardedMotion, HaltsAtTheExactInstantTheDetectionRadiusIsReached) {
  // Agent 0 moves at 10 u/tu towards a waiting agent 10 away: s = 4 is reached at t = 0.6.
  const std::vector<CandidatePair> pairs{{0, 1, {10.0, 0.0}}};
  const std::vector<MotionCommand> commands{moving({10.0, 0.0}, mask_of(kWait)), moving({})};
  const std::vector<Signal> signals{kGo, kWait};
  GuardedMotion motion;
  EXPECT_EQ(motion.resolve(pairs, commands, signals, kLimits), 1u);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 6.0);  // 0.6 tu at 10 u/tu
  EXPECT_EQ(motion.displacement(1), (Vec2{}));
}

TEST(GuardedMotion, ABlockedBodyStopsAtContactAndUnguardedOnesPass) {
  const std::vector<CandidatePair> pairs{{0, 1, {5.0, 0.0}}};
  const std::vector<Signal> signals{kGo, kWait};
  GuardedMotion motion;
  // Blocked by waiting bodies only: contact (distance 2) after 3 of the 5 units.
  const std::vector<MotionCommand> blocked{moving({5.0, 0.0}, 0, mask_of(kWait)), moving({})};
  EXPECT_EQ(motion.resolve(pairs, blocked, signals, kLimits), 1u);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 3.0);
  // Unguarded: moves the whole step, the encounter is still counted.
  const std::vector<MotionCommand> free{moving({5.0, 0.0}), moving({})};
  EXPECT_EQ(motion.resolve(pairs, free, signals, kLimits), 1u);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 5.0);
  EXPECT_EQ(GuardedMotion::count_encounters(pairs, free, kLimits), 1u);
}

TEST(GuardedMotion, AnAgentHaltedEarlyMissesWhatLayBeyondItsStop) {
  // 0 meets 1 at t = 0.2 and halts; 2 lay further on and is never met.
  const std::vector<CandidatePair> pairs{{0, 1, {6.0, 0.0}}, {0, 2, {12.0, 0.0}}};
  const std::vector<MotionCommand> commands{moving({10.0, 0.0}, mask_of(kWait)), moving({}),
                                            moving({})};
  const std::vector<Signal> signals{kGo, kWait, kWait};
  GuardedMotion motion;
  EXPECT_EQ(motion.resolve(pairs, commands, signals, kLimits), 1u);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 2.0);
}

TEST(GuardedMotion, AnAgentHaltedByWhatItPerceivesStandsForTheRestOfTheStep) {
  // 0 moves right at 10 u/tu, halts on waiting agents and is blocked by searching ones. It
  // perceives the waiting 1 (10 ahead) at t = 0.6 and halts at x = 6. At t = 0.83 the
  // searching 2, coming up from below, touches it from behind its path: a contact that lets
  // 0's command through, which must not start it again. The pair is solid (0's bit), so 2
  // slides around 0's body.
  const std::vector<CandidatePair> pairs{
      {0, 1, {10.0, 0.0}}, {0, 2, {5.0, -10.0}}, {1, 2, {-5.0, -10.0}}};
  const std::vector<MotionCommand> commands{moving({10.0, 0.0}, mask_of(kWait), mask_of(kGo)),
                                            moving({}), moving({0.0, 10.0})};
  const std::vector<Signal> signals{kGo, kWait, kGo};
  GuardedMotion motion;
  // 0 meets 1 and 2; 2 passes 1 at 5.
  EXPECT_EQ(motion.resolve(pairs, commands, signals, kLimits), 2u);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 6.0);
  EXPECT_EQ(motion.displacement(0).y, 0.0);
  const Vec2 two_from_zero = Vec2{5.0, -10.0} + motion.displacement(2) - motion.displacement(0);
  EXPECT_GE(norm(two_from_zero), 2.0 * (1.0 - 1e-9));
  EXPECT_LT(motion.displacement(2).x, 0.0);  // slid to the left of 0
}

// Solidity belongs to the pair, as in Box2D's contact filter: a body whose own command names
// no one is still stopped by a body whose blocked_by holds its signal.
TEST(GuardedMotion, APairIsSolidWhicheverSideHoldsTheBit) {
  const std::vector<CandidatePair> pairs{{0, 1, {5.0, 0.0}}};
  const std::vector<Signal> signals{kGo, kWait};
  GuardedMotion motion;
  const std::vector<MotionCommand> other_side{moving({5.0, 0.0}), moving({}, 0, mask_of(kGo))};
  motion.resolve(pairs, other_side, signals, kLimits);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 3.0);  // stopped at contact, distance 2
  const std::vector<MotionCommand> neither{moving({5.0, 0.0}), moving({}, 0, mask_of(kWait))};
  motion.resolve(pairs, neither, signals, kLimits);
  EXPECT_DOUBLE_EQ(motion.displacement(0).x, 5.0);  // 1 is blocked by waiting agents only
}

// A lattice of agents with axis-aligned unit-speed moves, who meet at exactly equal times
// all the time: random commands (some halting on waiting agents, some blocked by everyone),
// and every pair within 9 units.
struct Lattice {
  std::vector<Vec2> positions;
  std::vector<MotionCommand> commands;
  std::vector<Signal> signals;
  std::vector<CandidatePair> pairs;
};

Lattice random_lattice(std::mt19937_64& gen, int side, double spacing) {
  Lattice lattice;
  const Vec2 directions[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {0, 0}};
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      lattice.positions.push_back({x * spacing, y * spacing});
      const Vec2 v = 2.0 * directions[gen() % 5];
      const Signal signal = static_cast<Signal>(gen() % 2);
      lattice.commands.push_back(
          moving(v, gen() % 2 ? mask_of(kWait) : 0,
                 gen() % 3 == 0 ? SignalMask(mask_of(kGo) | mask_of(kWait)) : 0));
      lattice.signals.push_back(signal);
    }
  }
  for (std::uint32_t i = 0; i < lattice.positions.size(); ++i) {
    for (std::uint32_t j = i + 1; j < lattice.positions.size(); ++j) {
      const Vec2 d = lattice.positions[j] - lattice.positions[i];
      if (norm2(d) <= 9.0 * 9.0) lattice.pairs.push_back({i, j, d});
    }
  }
  return lattice;
}

std::vector<Vec2> displacements(const GuardedMotion& motion, std::size_t agents) {
  std::vector<Vec2> d;
  for (std::uint32_t a = 0; a < agents; ++a) d.push_back(motion.displacement(a));
  return d;
}

// Simultaneous events break ties on the pair's ids, so the result must not depend on the
// order the pairs are listed in.
TEST(GuardedMotion, ResultsDoNotDependOnTheOrderOfThePairs) {
  std::mt19937_64 gen(42);
  Lattice lattice = random_lattice(gen, 12, 5.0);
  const std::size_t agents = lattice.positions.size();
  GuardedMotion reference;
  const std::uint64_t encounters =
      reference.resolve(lattice.pairs, lattice.commands, lattice.signals, kLimits);
  const std::vector<Vec2> moved = displacements(reference, agents);
  EXPECT_GT(encounters, 0u);
  int changed = 0;  // halted or slid
  for (std::size_t a = 0; a < agents; ++a) changed += moved[a] != lattice.commands[a].velocity;
  EXPECT_GT(changed, 0);
  GuardedMotion motion;  // reused, as the engine does
  for (int shuffle = 0; shuffle < 5; ++shuffle) {
    std::shuffle(lattice.pairs.begin(), lattice.pairs.end(), gen);
    EXPECT_EQ(motion.resolve(lattice.pairs, lattice.commands, lattice.signals, kLimits),
              encounters);
    EXPECT_EQ(displacements(motion, agents), moved);
  }
}

// Islands (connected components of the pairs of moving agents; a fifth of the lattice stands)
// never affect each other, so processing them one after another gives what one time order
// gives: the same moves, walls touched, encounters, and agents met and bent (as sets: those
// lists are in processing order). Between walls too, where agents in no pair have wall events
// of their own.
void expect_the_same_step_by_island_and_by_time(std::mt19937_64& gen) {
  // 4.5 apart, pairs of lattice neighbours only, half of them dropped: many islands of a few
  // agents each (below the square lattice's percolation threshold).
  Lattice lattice = random_lattice(gen, 16, 4.5);
  std::erase_if(lattice.pairs,
                [&](const CandidatePair& p) { return norm2(p.offset) > 5.0 * 5.0 || gen() % 2; });
  MotionLimits walled = kLimits;
  walled.walls = true;
  walled.bounds = {{0.0, 0.0}, {15 * 4.5, 15 * 4.5}};
  const std::size_t agents = lattice.positions.size();
  auto sorted = [](std::span<const std::uint32_t> ids) {
    std::vector<std::uint32_t> v(ids.begin(), ids.end());
    std::sort(v.begin(), v.end());
    return v;
  };
  for (const MotionLimits& limits : {kLimits, walled}) {
    GuardedMotion by_time;
    by_time.set_event_order(EventOrder::ByTime);
    GuardedMotion by_island;
    by_island.set_event_order(EventOrder::ByIsland);
    for (int step = 0; step < 3; ++step) {  // reused, as the engine does
      const std::uint64_t encounters = by_time.resolve(lattice.pairs, lattice.commands,
                                                       lattice.signals, limits, lattice.positions);
      EXPECT_GT(encounters, 0u);
      EXPECT_EQ(by_island.resolve(lattice.pairs, lattice.commands, lattice.signals, limits,
                                  lattice.positions),
                encounters);
      const std::vector<Vec2> moved = displacements(by_time, agents);
      const std::vector<Vec2> moved_by_island = displacements(by_island, agents);
      EXPECT_TRUE(std::equal(moved.begin(), moved.end(), moved_by_island.begin(), same_bits));
      EXPECT_EQ(sorted(by_island.met_agents()), sorted(by_time.met_agents()));
      // The orders did differ: the encounters were met in another sequence.
      const auto met = by_time.met_agents();
      EXPECT_FALSE(std::ranges::equal(by_island.met_agents(), met));
      EXPECT_EQ(sorted(by_island.bent_agents()), sorted(by_time.bent_agents()));
      EXPECT_FALSE(by_time.bent_agents().empty());
      int walls = 0;
      for (std::uint32_t a = 0; a < agents; ++a) {
        EXPECT_EQ(by_island.wall_contacts(a), by_time.wall_contacts(a)) << a;
        walls += by_time.wall_contacts(a) != 0;
      }
      if (limits.walls) {
        EXPECT_GT(walls, 0);
      }
      std::shuffle(lattice.pairs.begin(), lattice.pairs.end(), gen);
    }
  }
}

TEST(GuardedMotion, OrderingEventsByIslandChangesNothing) {
  std::mt19937_64 gen(7);
  for (int lattice_number = 0; lattice_number < 20; ++lattice_number) {
    SCOPED_TRACE(lattice_number);
    expect_the_same_step_by_island_and_by_time(gen);
  }
}

}  // namespace
}  // namespace swarmagg
