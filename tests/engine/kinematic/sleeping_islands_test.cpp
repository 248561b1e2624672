// Sleep in the kinematic engine on hand-built scenes. Every engine here runs with its sleep
// check on: each step is also resolved in full, and sleeper_due_to_move() names any agent
// that slept though the full step would have moved it.
#include <gtest/gtest.h>

#include <bit>
#include <memory>
#include <vector>

#include "engine/kinematic/kinematic_engine.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {
namespace {

constexpr Signal kGo = 0;
constexpr Signal kWait = 1;
constexpr Signal kLeave = 2;

WorldSpec arena_world(double width, double height) {
  WorldSpec spec;
  spec.arena = {width, height, Topology::Torus};
  spec.robots.radius = 1.0;
  spec.robots.detection_radius = 4.0;
  spec.robots.speed = 1.0;
  spec.engine.dt = 0.1;
  return spec;
}

// A waiting body: solid to waiting and leaving bodies, moving (pressing) at `velocity`.
MotionCommand waiting(Vec2 velocity = {}) {
  return {velocity, 0, static_cast<SignalMask>(mask_of(kWait) | mask_of(kLeave)), 0};
}

MotionCommand searching(Vec2 velocity) {
  return {velocity, mask_of(kWait), mask_of(kWait), 0};
}

struct Scene {
  std::unique_ptr<Engine> engine;
  std::vector<MotionCommand> commands;
  std::vector<Signal> signals;

  Scene(const WorldSpec& spec, std::vector<Vec2> at, std::vector<MotionCommand> commanded,
        std::vector<Signal> shown)
      : engine(make_kinematic_engine(spec, at)),
        commands(std::move(commanded)),
        signals(std::move(shown)) {
    engine->set_sleep_checks(true);
  }
  std::size_t step() {
    engine->step(commands, signals);
    EXPECT_FALSE(engine->sleeper_due_to_move().has_value())
        << "agent " << *engine->sleeper_due_to_move() << " slept but was due to move";
    return engine->asleep_count();
  }
  Vec2 at(std::uint32_t agent) const { return engine->positions()[agent]; }
};

// Three waiting bodies in a row, touching (centres 2 apart): the ends press inwards, the
// middle one stands. Nobody can move; the ends' contact response halts them at once.
Scene pressed_row(const WorldSpec& spec, Vec2 left) {
  const ArenaGeometry arena = spec.arena.geometry();
  const std::vector<Vec2> at{left, arena.wrap(left + Vec2{2.0, 0.0}),
                             arena.wrap(left + Vec2{4.0, 0.0})};
  return Scene(spec, at, {waiting({0.3, 0.0}), waiting(), waiting({-0.3, 0.0})},
               {kWait, kWait, kWait});
}

TEST(SleepingIslands, APackedAggregateAtRestFallsAsleep) {
  Scene scene = pressed_row(arena_world(40.0, 40.0), {10.0, 10.0});
  const std::vector<Vec2> start(scene.engine->positions().begin(), scene.engine->positions().end());
  // The first step records what each agent did. From the second on, the row is the whole
  // world and at rest on the same pairs: one closed island, asleep.
  EXPECT_EQ(scene.step(), 0u);
  for (int k = 0; k < 20; ++k) EXPECT_EQ(scene.step(), 3u);
  for (std::uint32_t a = 0; a < 3; ++a) EXPECT_TRUE(same_bits(scene.at(a), start[a]));
  EXPECT_EQ(scene.engine->neighbours().of(1).size(), 2u);
}

TEST(SleepingIslands, ALeaverWakesItsNeighbours) {
  Scene scene = pressed_row(arena_world(40.0, 40.0), {10.0, 10.0});
  for (int k = 0; k < 5; ++k) scene.step();
  ASSERT_EQ(scene.step(), 3u);
  // The right end leaves: its command and signal change, so its whole island wakes.
  scene.commands[2] = {{1.0, 0.0}, 0, mask_of(kWait), mask_of(kWait)};
  scene.signals[2] = kLeave;
  EXPECT_EQ(scene.step(), 0u);
  EXPECT_GT(scene.at(2).x, 14.0);
  // Its neighbour's pull now finds no body in the way: the middle one presses right and
  // moves, which a sleeping island would have missed.
  scene.commands[1] = waiting({0.3, 0.0});
  const double middle = scene.at(1).x;
  EXPECT_EQ(scene.step(), 0u);
  EXPECT_GT(scene.at(1).x, middle);
}

TEST(SleepingIslands, AnApproachingAgentWakesTheMemberItWillTouch) {
  WorldSpec spec = arena_world(60.0, 40.0);
  Scene scene(spec, {{10.0, 10.0}, {12.0, 10.0}, {14.0, 10.0}, {24.0, 10.0}},
              {waiting({0.3, 0.0}), waiting(), waiting({-0.3, 0.0}), searching({-1.0, 0.0})},
              {kWait, kWait, kWait, kGo});
  scene.step();
  scene.step();
  // The row sleeps while the searcher is still beyond the pair reach (s + 2 v dt = 4.2).
  EXPECT_EQ(scene.step(), 3u);
  int woke_at = -1;
  for (int k = 0; k < 80 && woke_at < 0; ++k) {
    if (scene.step() == 0u) woke_at = k;
  }
  ASSERT_GE(woke_at, 0) << "the row never woke";
  // It woke before the searcher perceived it: the step that woke it halted the searcher at
  // s = 4 from the row's end, or it is still on its way.
  EXPECT_GT(scene.at(3).x - scene.at(2).x, 4.0 - 1e-6);
  for (int k = 0; k < 5 && scene.at(3).x - scene.at(2).x > 4.0; ++k) scene.step();
  EXPECT_NEAR(scene.at(3).x - scene.at(2).x, 4.0, 1e-6);
  // It joins (stands and shows WAIT, as a controller would have it): then all four rest, and
  // from the third step on sleep as one island.
  scene.commands[3] = waiting();
  scene.signals[3] = kWait;
  scene.step();
  scene.step();
  EXPECT_EQ(scene.step(), 4u);
}

TEST(SleepingIslands, ARowAcrossTheTorusSeamSleepsInPlace) {
  Scene scene = pressed_row(arena_world(40.0, 40.0), {37.0, 20.0});  // 37, 39, 41 = 1
  const std::vector<Vec2> start(scene.engine->positions().begin(), scene.engine->positions().end());
  EXPECT_DOUBLE_EQ(start[2].x, 1.0);
  scene.step();
  scene.step();
  for (int k = 0; k < 10; ++k) EXPECT_EQ(scene.step(), 3u);
  for (std::uint32_t a = 0; a < 3; ++a) EXPECT_TRUE(same_bits(scene.at(a), start[a]));
  // Pulling the middle one across the seam wakes the row, which then moves as usual.
  scene.commands[1] = waiting({0.0, 0.5});
  EXPECT_EQ(scene.step(), 0u);
  EXPECT_GT(scene.at(1).y, 20.0);
}

// Without checks, a world asleep whole that is given the same commands and signals again is
// not decided again: it must still be exactly the world that would have been decided.
TEST(SleepingIslands, AWorldAsleepWholeStaysAsleepOnRepeatedInputsAndWakesOnAnyChange) {
  Scene scene = pressed_row(arena_world(40.0, 40.0), {10.0, 10.0});
  scene.engine->set_sleep_checks(false);
  const std::vector<Vec2> start(scene.engine->positions().begin(), scene.engine->positions().end());
  scene.step();
  for (int k = 0; k < 10; ++k) ASSERT_EQ(scene.step(), 3u);
  const std::uint64_t generation = scene.engine->neighbours().generation();
  for (int k = 0; k < 10; ++k) EXPECT_EQ(scene.step(), 3u);
  for (std::uint32_t a = 0; a < 3; ++a) EXPECT_TRUE(same_bits(scene.at(a), start[a]));
  EXPECT_EQ(scene.engine->neighbours().generation(), generation);
  // A signal alone changes (the middle one shows LEAVE, standing): the world is decided
  // again; its inputs differ from the last step's, so nobody sleeps in this step.
  scene.signals[1] = kLeave;
  EXPECT_EQ(scene.step(), 0u);
  // A command changes: the middle one moves off the row's line, which it could not asleep.
  scene.signals[1] = kWait;
  scene.commands[1] = waiting({0.0, 0.5});
  EXPECT_EQ(scene.step(), 0u);
  EXPECT_GT(scene.at(1).y, start[1].y);
}

// Bodies that stay where they were count as pressing at rest whether they halted at once
// or within a rounding error of it: a pressed row sleeps after a moving phase too.
TEST(SleepingIslands, ARowThatComesToRestAfterMovingFallsAsleep) {
  WorldSpec spec = arena_world(40.0, 40.0);
  Scene scene(spec, {{10.0, 10.0}, {12.0, 10.0}, {14.5, 10.0}},
              {waiting({0.3, 0.0}), waiting(), waiting({-0.3, 0.0})}, {kWait, kWait, kWait});
  // The right end closes the half-unit gap in about two steps, then presses at rest.
  std::size_t asleep = 0;
  for (int k = 0; k < 20 && asleep == 0; ++k) asleep = scene.step();
  EXPECT_EQ(asleep, 3u);
  EXPECT_NEAR(scene.at(2).x - scene.at(1).x, 2.0, 1e-6);
}

TEST(SleepingIslands, AMovingSwarmNeverSleeps) {
  Scene scene(arena_world(40.0, 40.0), {{5.0, 5.0}, {20.0, 20.0}},
              {searching({1.0, 0.0}), searching({0.0, 1.0})}, {kGo, kGo});
  for (int k = 0; k < 10; ++k) EXPECT_EQ(scene.step(), 0u);
}

}  // namespace
}  // namespace swarmagg
