#include "engine/kinematic/guarded_motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
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

// Simultaneous events break ties on the pair's ids, so the result must not depend on the
// order the pairs are listed in. Agents on a lattice with axis-aligned unit-speed moves meet
// at exactly equal times all the time.
TEST(GuardedMotion, ResultsDoNotDependOnTheOrderOfThePairs) {
  std::mt19937_64 gen(42);
  const int side = 12;
  const double spacing = 5.0;
  std::vector<Vec2> positions;
  std::vector<MotionCommand> commands;
  std::vector<Signal> signals;
  const Vec2 directions[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {0, 0}};
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      positions.push_back({x * spacing, y * spacing});
      const Vec2 v = 2.0 * directions[gen() % 5];
      const Signal signal = static_cast<Signal>(gen() % 2);
      commands.push_back(moving(v, gen() % 2 ? mask_of(kWait) : 0,
                                gen() % 3 == 0 ? SignalMask(mask_of(kGo) | mask_of(kWait)) : 0));
      signals.push_back(signal);
    }
  }
  std::vector<CandidatePair> pairs;
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    for (std::uint32_t j = i + 1; j < positions.size(); ++j) {
      const Vec2 d = positions[j] - positions[i];
      if (norm2(d) <= 9.0 * 9.0) pairs.push_back({i, j, d});
    }
  }
  GuardedMotion reference;
  const std::uint64_t encounters = reference.resolve(pairs, commands, signals, kLimits);
  auto displacements = [&](const GuardedMotion& m) {
    std::vector<Vec2> d;
    for (std::uint32_t a = 0; a < positions.size(); ++a) d.push_back(m.displacement(a));
    return d;
  };
  const std::vector<Vec2> moved = displacements(reference);
  EXPECT_GT(encounters, 0u);
  int changed = 0;  // halted or slid
  for (std::size_t a = 0; a < moved.size(); ++a) changed += moved[a] != commands[a].velocity;
  EXPECT_GT(changed, 0);
  GuardedMotion motion;  // reused, as the engine does
  for (int shuffle = 0; shuffle < 5; ++shuffle) {
    std::shuffle(pairs.begin(), pairs.end(), gen);
    EXPECT_EQ(motion.resolve(pairs, commands, signals, kLimits), encounters);
    EXPECT_EQ(displacements(motion), moved);
  }
}

}  // namespace
}  // namespace swarmagg
