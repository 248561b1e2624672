#include "engine/kinematic/kinematic_engine.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/arena_geometry.hpp"

namespace swarmagg {
namespace {

constexpr Signal kGo = 0;
constexpr Signal kWait = 1;

WorldSpec arena_world(double width, double height, Topology topology = Topology::Torus) {
  WorldSpec spec;
  spec.arena = {width, height, topology};
  spec.robots.radius = 1.0;
  spec.robots.detection_radius = 4.0;
  spec.robots.speed = 1.0;
  spec.engine.dt = 0.1;
  return spec;
}

MotionCommand moving(Vec2 velocity, SignalMask halt_on = 0, SignalMask blocked_by = 0) {
  return MotionCommand{velocity, halt_on, blocked_by, 0};
}

TEST(KinematicEngine, NeighbourListsMatchBruteForceAndAreSortedByDistance) {
  WorldSpec spec = arena_world(60.0, 40.0);
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> ux(0.0, 60.0), uy(0.0, 40.0);
  std::vector<Vec2> positions(300);
  for (Vec2& p : positions) p = {ux(gen), uy(gen)};
  auto engine = make_kinematic_engine(spec, positions);
  const ArenaGeometry arena = spec.arena.geometry();
  for (std::uint32_t i = 0; i < positions.size(); ++i) {
    std::vector<std::uint32_t> expected;
    for (std::uint32_t j = 0; j < positions.size(); ++j) {
      if (j != i && arena.distance(positions[i], positions[j]) <= 4.0) expected.push_back(j);
    }
    std::vector<std::uint32_t> found;
    double last = 0.0;
    for (const Neighbour& n : engine->neighbours().of(i)) {
      found.push_back(n.id);
      EXPECT_GE(n.distance, last);
      last = n.distance;
      EXPECT_NEAR(n.distance, arena.distance(positions[i], positions[n.id]), 1e-12);
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected) << "agent " << i;
  }
}

TEST(KinematicEngine, FastGhostsCrossingInOneStepCountOneEncounter) {
  WorldSpec spec = arena_world(200.0, 200.0);
  spec.robots.speed = 150.0;  // 15 u per step, nearly four detection radii
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{90.0, 100.0}, {110.0, 101.0}});
  const std::vector<MotionCommand> commands{moving({150.0, 0.0}), moving({-150.0, 0.0})};
  const std::vector<Signal> signals{kGo, kGo};
  // The gap of 20 closes by 30 in one step: they pass within 1 u of each other mid-step,
  // then move apart. A check at step ends alone would never see them within s.
  EXPECT_EQ(engine->step(commands, signals).encounters, 1u);
  EXPECT_NEAR(engine->positions()[0].x, 105.0, 1e-12);
  EXPECT_NEAR(engine->positions()[1].x, 95.0, 1e-12);
  EXPECT_EQ(engine->step(commands, signals).encounters, 0u);
}

TEST(KinematicEngine, GuardedMoveHaltsAtTheDetectionRadiusEvenWhenFast) {
  WorldSpec spec = arena_world(200.0, 200.0);
  spec.robots.speed = 30.0;  // 3 u per step
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{50.0, 50.0}, {61.0, 50.0}});
  const std::vector<MotionCommand> commands{moving({30.0, 0.0}, mask_of(kWait)), moving({})};
  const std::vector<Signal> signals{kGo, kWait};
  EXPECT_EQ(engine->step(commands, signals).encounters, 0u);  // 11 -> 8
  EXPECT_EQ(engine->step(commands, signals).encounters, 0u);  // 8 -> 5
  EXPECT_EQ(engine->step(commands, signals).encounters, 1u);  // reaches 4 a third in
  const double gap = engine->positions()[1].x - engine->positions()[0].x;
  EXPECT_LE(gap, 4.0);
  EXPECT_GT(gap, 4.0 - 1e-6);
  ASSERT_EQ(engine->neighbours().of(0).size(), 1u);
  EXPECT_EQ(engine->neighbours().of(0)[0].id, 1u);
}

TEST(KinematicEngine, GuardedMoveHaltsAcrossTheSeam) {
  WorldSpec spec = arena_world(100.0, 100.0);
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{98.0, 1.0}, {3.0, 1.0}});
  const std::vector<MotionCommand> commands{moving({10.0, 0.0}, mask_of(kGo)),
                                            moving({-10.0, 0.0}, mask_of(kGo))};
  const std::vector<Signal> signals{kGo, kGo};
  EXPECT_EQ(engine->step(commands, signals).encounters, 1u);  // 5 apart, closing 2 per step
  const ArenaGeometry arena = spec.arena.geometry();
  const double gap = arena.distance(engine->positions()[0], engine->positions()[1]);
  EXPECT_LE(gap, 4.0);
  EXPECT_GT(gap, 4.0 - 1e-6);
  EXPECT_NEAR(engine->positions()[0].x, 98.5, 1e-6);
  EXPECT_NEAR(engine->positions()[1].x, 2.5, 1e-6);
}

TEST(KinematicEngine, UnguardedAgentsPassOverEachOther) {
  WorldSpec spec = arena_world(100.0, 100.0);
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{40.0, 50.0}, {50.0, 50.0}});
  const std::vector<MotionCommand> commands{moving({10.0, 0.0}), moving({})};
  const std::vector<Signal> signals{kGo, kWait};
  for (int k = 0; k < 20; ++k) engine->step(commands, signals);
  EXPECT_NEAR(engine->positions()[0].x, 60.0, 1e-9);
}

TEST(KinematicEngine, BlockedBodyStopsAtContactAndMayStillMoveAway) {
  WorldSpec spec = arena_world(100.0, 100.0);
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{40.0, 50.0}, {50.0, 50.0}});
  const std::vector<Signal> signals{kGo, kWait};
  const std::vector<MotionCommand> towards{moving({10.0, 0.0}, 0, mask_of(kWait)), moving({})};
  for (int k = 0; k < 20; ++k) engine->step(towards, signals);
  EXPECT_NEAR(engine->positions()[0].x, 48.0, 1e-9);  // bodies of radius 1 touch at 2
  const std::vector<MotionCommand> away{moving({-10.0, 0.0}, 0, mask_of(kWait)), moving({})};
  engine->step(away, signals);
  EXPECT_NEAR(engine->positions()[0].x, 47.0, 1e-9);
}

// Compaction's moves (docs/controllers.md): two waiting bodies closing in on each other, each
// blocked by the other, stop together at contact.
TEST(KinematicEngine, TwoBlockedBodiesMovingTogetherStopAtContact) {
  WorldSpec spec = arena_world(100.0, 100.0);
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{48.25, 50.0}, {51.75, 50.0}});
  const std::vector<Signal> signals{kWait, kWait};
  const std::vector<MotionCommand> closing{moving({10.0, 0.0}, 0, mask_of(kWait)),
                                           moving({-10.0, 0.0}, 0, mask_of(kWait))};
  engine->step(closing, signals);
  EXPECT_NEAR(engine->positions()[0].x, 49.0, 1e-9);
  EXPECT_NEAR(engine->positions()[1].x, 51.0, 1e-9);
}

// Two pairs of touching waiting bodies: 0 and 1 pressed into each other (0 at a slant), 2
// pushed sideways along 3.
struct PressedPairs {
  const std::vector<Vec2> start{{49.0, 50.0}, {51.0, 50.0}, {60.0, 50.0}, {62.0, 50.0}};
  const std::vector<Signal> signals{kWait, kWait, kWait, kWait};
  static constexpr SignalMask kSolid = mask_of(kWait);
  const std::vector<MotionCommand> pressed{
      moving({0.5, 0.1}, 0, kSolid), moving({-0.5, 0.0}, 0, kSolid),  // into each other
      moving({0.0, 1.0}, 0, kSolid), moving({}, 0, kSolid)};          // along the other
};

// Halting at contacts, bodies already touching and pressed towards each other do not move at
// all (they halt at the start of the step), while one pushed sideways along the other slides.
TEST(KinematicEngine, TouchingBlockedBodiesPressedTogetherHaltAtOnceWhenContactsStop) {
  const PressedPairs scene;
  WorldSpec spec = arena_world(100.0, 100.0);
  spec.engine.contact = ContactResponse::Stop;
  auto engine = make_kinematic_engine(spec, scene.start);
  for (int k = 0; k < 10; ++k) engine->step(scene.pressed, scene.signals);
  EXPECT_EQ(engine->positions()[0], scene.start[0]);
  EXPECT_EQ(engine->positions()[1], scene.start[1]);
  EXPECT_NEAR(engine->positions()[2].y, 51.0, 1e-9);
}

// Sliding (the default), a body pressed into another keeps the part of its velocity along
// the contact; pressed head on it has none and halts, like both bodies under `stop`.
TEST(KinematicEngine, TouchingBlockedBodiesSlideAlongEachOtherOrHaltHeadOn) {
  const PressedPairs scene;
  auto engine = make_kinematic_engine(arena_world(100.0, 100.0), scene.start);
  const SignalMask solid = PressedPairs::kSolid;
  const std::vector<MotionCommand> head_on{moving({0.5, 0.0}, 0, solid),
                                           moving({-0.5, 0.0}, 0, solid), moving({}, 0, solid),
                                           moving({}, 0, solid)};
  engine->step(head_on, scene.signals);
  EXPECT_NEAR(engine->positions()[0].x, scene.start[0].x, 1e-9);
  EXPECT_NEAR(engine->positions()[1].x, scene.start[1].x, 1e-9);
  for (int k = 0; k < 10; ++k) engine->step(scene.pressed, scene.signals);
  const Vec2 p0 = engine->positions()[0], p1 = engine->positions()[1];
  // 0 slides up round 1; once off its line, 1 slides down round 0. They keep touching and
  // never sink into each other.
  EXPECT_GT(p0.y, scene.start[0].y + 0.05);
  EXPECT_LT(p1.y, scene.start[1].y);
  EXPECT_GE(norm(p1 - p0), 2.0 - 1e-9);
  EXPECT_LT(norm(p1 - p0), 2.0 + 1e-3);  // straight slides drift off the circle to second order
  EXPECT_NEAR(engine->positions()[2].y, 51.0, 1e-9);
}

// A body pressed nearly head-on into another slides only while what the contact lets through
// reaches 1 % of the nominal speed (1 here); slower, it halts instead of creeping.
TEST(KinematicEngine, ASlideSlowerThanTheMinimumHalts) {
  const SignalMask solid = mask_of(kWait);
  const std::vector<Signal> signals{kWait, kWait};
  for (const double sideways : {0.008, 0.02}) {
    auto engine = make_kinematic_engine(arena_world(100.0, 100.0),
                                        std::vector<Vec2>{{49.0, 50.0}, {51.0, 50.0}});
    const std::vector<MotionCommand> pressed{moving({0.5, sideways}, 0, solid),
                                             moving({}, 0, solid)};
    engine->step(pressed, signals);
    const Vec2 moved = engine->positions()[0] - Vec2{49.0, 50.0};
    if (sideways < 0.01) {
      EXPECT_EQ(moved, (Vec2{})) << sideways;
    } else {
      EXPECT_NEAR(moved.y, sideways * 0.1, 1e-12);
      EXPECT_LE(moved.x, 0.0);
    }
  }
}

// A waiting body (0) pulled straight down into the wedge of two touching below it is jammed:
// it presses without moving. One of the two (1) moves away, pressing into nothing, and must
// go on for the whole step. It used to halt at the start of every step, held for good by a
// neighbour that never moved: when their pair's contact came first, both answered it, the
// presser by halting in the wedge and the other, pressed on, by halting too. The jammed body
// sits a rounding error inside contact, as slides leave bodies.
TEST(KinematicEngine, ABodyMovingAwayGoesOnWhileAJammedNeighbourPressesIntoIt) {
  const double up = std::sqrt(3.0) * (1.0 - 1e-12);
  auto engine = make_kinematic_engine(
      arena_world(100.0, 100.0), std::vector<Vec2>{{50.0, 50.0 + up}, {51.0, 50.0}, {49.0, 50.0}});
  const SignalMask solid = mask_of(kWait) | mask_of(kGo);
  const std::vector<Signal> signals{kWait, kGo, kWait};
  const std::vector<MotionCommand> commands{moving({0.0, -1.0}, 0, solid),
                                            moving({1.0, 0.0}, 0, solid), moving({}, 0, solid)};
  for (int k = 0; k < 3; ++k) engine->step(commands, signals);
  EXPECT_NEAR(engine->positions()[1].x, 51.3, 1e-9);
  EXPECT_NEAR(engine->positions()[1].y, 50.0, 1e-12);
}

TEST(KinematicEngine, AHaltedAgentDoesNotMeetWhatLayBeyondItsStop) {
  WorldSpec spec = arena_world(100.0, 100.0);
  spec.robots.speed = 100.0;
  // Agent 0 heads for 1 (stops 4 short of it); agent 2 waits 3 beyond 1, so 0 never
  // comes within 4 of it. Without the guard, 0 would pass both.
  const std::vector<Vec2> start{{40.0, 50.0}, {50.0, 50.0}, {53.0, 50.0}};
  const std::vector<Signal> signals{kGo, kWait, kWait};
  auto guarded = make_kinematic_engine(spec, start);
  const std::vector<MotionCommand> halt{moving({100.0, 0.0}, mask_of(kWait)), moving({}),
                                        moving({})};
  EXPECT_EQ(guarded->step(halt, signals).encounters, 1u);
  EXPECT_NEAR(guarded->positions()[0].x, 46.0, 1e-6);
  auto ghost = make_kinematic_engine(spec, start);
  const std::vector<MotionCommand> pass{moving({100.0, 0.0}), moving({}), moving({})};
  EXPECT_EQ(ghost->step(pass, signals).encounters, 2u);
}

TEST(KinematicEngine, WallsReflectBodiesAndReportWhichAxis) {
  WorldSpec spec = arena_world(50.0, 50.0, Topology::Walls);
  auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{48.5, 25.0}});
  const std::vector<MotionCommand> commands{moving({10.0, 0.0})};
  engine->step(commands, std::vector<Signal>{kGo});
  EXPECT_NEAR(engine->positions()[0].x, 48.5, 1e-12);  // 49.5 reflected off 49 (= 50 - r)
  EXPECT_EQ(engine->reflections()[0], ReflectedX);
}

// A body solid to others meets a wall inside the guarded move, where a mirrored excess could
// sink it into a body next to the wall: it slides along the wall (or halts, under stop) and
// reports the axis so that its controller turns.
TEST(KinematicEngine, SolidBodiesMeetWallsInsideTheGuardedMove) {
  for (const ContactResponse response : {ContactResponse::Slide, ContactResponse::Stop}) {
    WorldSpec spec = arena_world(50.0, 50.0, Topology::Walls);
    spec.engine.contact = response;
    // Agent 0 reaches the wall at x = 49 (= 50 - r) at t = 0.05, y = 24.5. Mirrored after
    // the move, it would end at (48.9, 24), 1.96 from agent 1, which is solid to it.
    auto engine = make_kinematic_engine(spec, std::vector<Vec2>{{48.9, 25.0}, {47.0, 23.5}});
    const std::vector<MotionCommand> commands{moving({2.0, -10.0}, 0, mask_of(kWait)), moving({})};
    engine->step(commands, std::vector<Signal>{kGo, kWait});
    const Vec2 p = engine->positions()[0];
    EXPECT_LE(p.x, 49.0 + 1e-12);
    EXPECT_GE(norm(p - engine->positions()[1]), 2.0 - 1e-9);
    EXPECT_EQ(engine->reflections()[0], ReflectedX);
    if (response == ContactResponse::Stop) {
      EXPECT_NEAR(p.x, 49.0, 1e-12);  // halted where it reached the wall
      EXPECT_NEAR(p.y, 24.5, 1e-12);
    } else {
      EXPECT_NEAR(p.x, 49.0, 1e-9);  // slid down the wall for the remaining 0.05 tu
      EXPECT_NEAR(p.y, 24.0, 1e-9);
    }
  }
}

}  // namespace
}  // namespace swarmagg
