// The Box2D engine's contract (engine.hpp, motion_command.hpp) away from the seam: neighbour
// lists, solidity rule, guarded moves, repulsion, speed cap, walls, overlap, determinism.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include "core/errors.hpp"
#include "engine/box2d/box2d_test_support.hpp"
#include "engine/engine.hpp"

namespace swarmagg {
namespace {

using namespace swarmagg::testing;

std::vector<MotionCommand> moving(const std::vector<Vec2>& headings, double speed,
                                  SignalMask blocked_by = 0) {
  std::vector<MotionCommand> commands(headings.size());
  for (std::size_t i = 0; i < headings.size(); ++i) {
    commands[i].velocity = headings[i] * speed;
    commands[i].blocked_by = blocked_by;
  }
  return commands;
}

// Every pair within the sensing radius, and only those, nearest first, with minimum-image
// offsets; pairs within 1e-4 of the radius may go either way (Box2D works in float).
void expect_brute_force_neighbours(const Engine& engine, const ArenaGeometry& geometry,
                                   double radius) {
  const auto p = engine.positions();
  const NeighbourLists& lists = engine.neighbours();
  ASSERT_EQ(lists.agent_count(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::vector<AgentId> listed;
    double last = 0.0;
    for (const Neighbour& n : lists.of(static_cast<AgentId>(i))) {
      listed.push_back(n.id);
      const Vec2 d = geometry.displacement(p[i], p[n.id]);
      ASSERT_NEAR(n.offset.x, d.x, 1e-12);
      ASSERT_NEAR(n.offset.y, d.y, 1e-12);
      ASSERT_NEAR(n.distance, norm(d), 1e-12);
      ASSERT_LE(n.distance, radius);
      ASSERT_GE(n.distance, last) << "not sorted nearest first";
      last = n.distance;
    }
    std::sort(listed.begin(), listed.end());
    ASSERT_TRUE(std::adjacent_find(listed.begin(), listed.end()) == listed.end()) << "duplicate";
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i) continue;
      const double d = geometry.distance(p[i], p[j]);
      if (std::abs(d - radius) < 1e-4) continue;
      const bool found = std::binary_search(listed.begin(), listed.end(), static_cast<AgentId>(j));
      ASSERT_EQ(found, d <= radius) << "agents " << i << ", " << j << " at distance " << d;
    }
  }
}

TEST(Box2DEngine, NeighbourListsMatchBruteForce) {
  const WorldSpec spec = box2d_world(80.0, 60.0, 300);
  const auto start = random_positions(spec, 300, 2.0, 11);
  auto engine = make_box2d_engine(spec, start);
  const ArenaGeometry geometry = spec.arena.geometry();
  expect_brute_force_neighbours(*engine, geometry, 4.0);        // the initial placement too
  const auto commands = moving(random_headings(300, 12), 1.0);  // ghosts: they pass
  const std::vector<Signal> signals(300, kGo);
  for (int k = 0; k < 300; ++k) {
    engine->step(commands, signals);
    expect_brute_force_neighbours(*engine, geometry, 4.0);
  }
}

// Soysal's controller reads up to its approach radius: a second, larger sensor.
TEST(Box2DEngine, NeighbourListsReachTheSensingRadius) {
  WorldSpec spec = box2d_world(80.0, 60.0, 200);
  spec.controller.type = "soysal";
  spec.controller.approach_radius = 12.0;
  const auto start = random_positions(spec, 200, 2.0, 21);
  auto engine = make_box2d_engine(spec, start);
  const ArenaGeometry geometry = spec.arena.geometry();
  const auto commands = moving(random_headings(200, 22), 1.0);
  const std::vector<Signal> signals(200, kGo);
  std::uint64_t encounters = 0;
  for (int k = 0; k < 200; ++k) {
    encounters += engine->step(commands, signals).encounters;
    expect_brute_force_neighbours(*engine, geometry, 12.0);
  }
  EXPECT_GT(encounters, 0u);  // still counted at s, by the detection sensors
}

TEST(Box2DEngine, SolidityIsEitherBodysBlockedBy) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const std::vector<Vec2> start{{45.0, 50.0}, {55.0, 50.0}};
  const std::vector<Signal> signals{kGo, kWait};
  auto run = [&](SignalMask blocked_a, SignalMask blocked_b) {
    auto engine = make_box2d_engine(spec, start);
    std::vector<MotionCommand> c(2);
    c[0].velocity = {1.0, 0.0};
    c[1].velocity = {-1.0, 0.0};
    c[0].blocked_by = blocked_a;
    c[1].blocked_by = blocked_b;
    for (int k = 0; k < 60; ++k) engine->step(c, signals);
    return engine->positions()[0].x;  // passed through: 51; blocked: about 49
  };
  EXPECT_NEAR(run(0, 0), 51.0, 1e-3);
  EXPECT_NEAR(run(mask_of(kWait), 0), 49.0, 0.02);             // A respects the waiting B
  EXPECT_NEAR(run(0, mask_of(kGo)), 49.0, 0.02);               // B respects the going A
  EXPECT_NEAR(run(mask_of(kGo), mask_of(kWait)), 51.0, 1e-3);  // neither's signal matches
}

// Two bodies passing over each other are told mid-way that they are solid: they are pushed
// apart at once (the new contact is found before the solver runs), not left overlapping.
TEST(Box2DEngine, BecomingSolidSeparatesOverlappingBodies) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const std::vector<Vec2> start{{50.0, 50.0}, {51.0, 50.0}};
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> c(2);
  const std::vector<Signal> signals{kGo, kGo};
  engine->step(c, signals);
  EXPECT_NEAR(engine->positions()[1].x - engine->positions()[0].x, 1.0, 1e-5);
  c[0].blocked_by = kAll;
  engine->step(c, signals);
  EXPECT_GT(engine->positions()[1].x - engine->positions()[0].x, 1.0 + 1e-3);
  for (int k = 0; k < 60; ++k) engine->step(c, signals);
  EXPECT_NEAR(engine->positions()[1].x - engine->positions()[0].x, 2.0, 0.02);
}

// A guarded move stops when an agent showing a halting signal comes within s, overshooting
// by at most one substep of travel.
TEST(Box2DEngine, GuardedMoveStopsAtTheDetectionRadius) {
  for (int substeps : {1, 4}) {
    WorldSpec spec = box2d_world(100.0, 100.0, 3);
    spec.engine.box2d.substeps = substeps;
    // Agent 2 (another GO agent) lies across the path but does not halt agent 0.
    const std::vector<Vec2> start{{40.0, 50.0}, {52.03, 50.0}, {45.0, 53.0}};
    auto engine = make_box2d_engine(spec, start);
    std::vector<MotionCommand> c(3);
    c[0].velocity = {1.0, 0.0};
    c[0].halt_on = mask_of(kWait);
    const std::vector<Signal> signals{kGo, kWait, kGo};
    double x_at_halt = 0.0;
    int halted_at = -1;
    for (int k = 0; k < 100 && halted_at < 0; ++k) {
      const std::uint64_t met = engine->step(c, signals).encounters;
      const double gap = engine->positions()[1].x - engine->positions()[0].x;
      if (gap <= 4.0) {
        halted_at = k;
        x_at_halt = engine->positions()[0].x;
        EXPECT_GE(met, 1u);
        EXPECT_GE(gap, 4.0 - 0.1 / substeps - 1e-5) << substeps << " substeps";
      }
    }
    ASSERT_GE(halted_at, 0);
    EXPECT_EQ(halted_at, 80);  // 8.03 - 4 = 4.03 u at 0.1 u per step: during step 81
    // The gap reached s at x = 48.03; the body stops after the (sub)step in which it did.
    EXPECT_LE(x_at_halt, 48.03 + 0.1 / substeps + 1e-4) << substeps << " substeps";
  }
}

TEST(Box2DEngine, WaitingAgentsRepelLeavingOnesWithinS) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const std::vector<Vec2> start{{50.0, 50.0}, {52.5, 50.0}};
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> c(2);
  c[1].repelled_by = mask_of(kWait);
  const std::vector<Signal> signals{kWait, kLeave};
  engine->step(c, signals);
  // force 20 (1 - 2.5/4) = 7.5 per unit mass: v = 0.75, x += 0.1 v (semi-implicit Euler).
  EXPECT_NEAR(engine->positions()[1].x - 52.5, 0.075, 1e-5);
  EXPECT_EQ(engine->positions()[0].x, 50.0);  // one-sided: the waiting agent holds still
  for (int k = 0; k < 300; ++k) engine->step(c, signals);
  const double gap = engine->positions()[1].x - engine->positions()[0].x;
  EXPECT_GT(gap, 3.9);  // pushed out to about s, where the force fades
  EXPECT_LE(gap, 4.0 + 1e-6);
  EXPECT_NEAR(engine->positions()[1].y, 50.0, 1e-5);
}

TEST(Box2DEngine, FastAgentsAreSubsteppedNotClamped) {
  for (double speed : {30.0, 700.0}) {
    WorldSpec spec = box2d_world(400.0, 300.0, 2);
    spec.robots.speed = speed;
    const std::vector<Vec2> start{{10.0, 10.0}, {200.0, 150.0}};
    auto engine = make_box2d_engine(spec, start);
    std::vector<MotionCommand> c(2);
    c[0].velocity = Vec2{0.6, 0.8} * speed;
    const std::vector<Signal> signals{kGo, kGo};
    const ArenaGeometry geometry = spec.arena.geometry();
    Vec2 last = start[0];
    for (int k = 0; k < 10; ++k) {
      engine->step(c, signals);
      const Vec2 moved = geometry.displacement(last, engine->positions()[0]);
      EXPECT_NEAR(moved.x, 0.06 * speed, 2e-3 * speed / 30.0) << speed;
      EXPECT_NEAR(moved.y, 0.08 * speed, 2e-3 * speed / 30.0) << speed;
      last = engine->positions()[0];
    }
  }
}

// Fast bodies still collide instead of tunnelling through each other.
TEST(Box2DEngine, FastHeadOnBodiesDoNotTunnel) {
  WorldSpec spec = box2d_world(200.0, 200.0, 2);
  spec.robots.speed = 40.0;  // 4 u per step, twice the body diameter
  const std::vector<Vec2> start{{80.0, 100.0}, {120.3, 100.0}};
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> c(2);
  c[0].velocity = {40.0, 0.0};
  c[1].velocity = {-40.0, 0.0};
  c[0].blocked_by = c[1].blocked_by = kAll;
  const std::vector<Signal> signals{kGo, kGo};
  for (int k = 0; k < 20; ++k) {
    engine->step(c, signals);
    EXPECT_LT(engine->positions()[0].x, engine->positions()[1].x) << "tunnelled at step " << k;
  }
  EXPECT_NEAR(engine->positions()[1].x - engine->positions()[0].x, 2.0, 0.05);
}

TEST(Box2DEngine, RefusesWhatItCannotSimulate) {
  WorldSpec spec = box2d_world(100.0, 100.0, 1);
  const std::vector<Vec2> one{{50.0, 50.0}};
  spec.robots.speed = 1e6;
  EXPECT_THROW(make_box2d_engine(spec, one), InputError);
  spec = box2d_world(10.0, 100.0, 1);  // images of both edges would overlap
  EXPECT_THROW(make_box2d_engine(spec, std::vector<Vec2>{{5.0, 50.0}}), InputError);
  spec = box2d_world(100.0, 100.0, 1, Topology::Walls);
  EXPECT_THROW(make_box2d_engine(spec, std::vector<Vec2>{{150.0, 50.0}}), InputError);
  spec = box2d_world(100.0, 100.0, 1);
  spec.engine.box2d.substeps = 0;
  EXPECT_THROW(make_box2d_engine(spec, one), InputError);
}

// Box2D rounds positions to floats: in an arena 10^5 wide a move of 0.1 is 12.8 float spacings,
// and agents' speeds came out up to 4 % off. `validate` checks this too (check_engine_world).
std::string resolution_error(double width, double speed, int substeps) {
  WorldSpec spec = box2d_world(width, 100.0, 1);
  spec.robots.speed = speed;
  spec.engine.box2d.substeps = substeps;
  try {
    check_engine_world(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Box2DEngine, RefusesArenasWherePositionsCannotResolveASubstepsMove) {
  EXPECT_THAT(resolution_error(100000.0, 1.0, 1),
              ::testing::HasSubstr("engine.type: box2d keeps positions in single precision: in "
                                   "an arena 100000 wide a substep moves an agent 0.1"));
  EXPECT_THAT(resolution_error(100000.0, 1.0, 1), ::testing::HasSubstr("12.8 times"));
  EXPECT_EQ(resolution_error(16000.0, 1.0, 1), "no error");  // 51 spacings
  EXPECT_THAT(resolution_error(16000.0, 1.0, 4), ::testing::HasSubstr("single precision"));
  // At v = 10 a step of 1 u is cut into 2 substeps of 0.5 u (half the radius): 32 spacings.
  EXPECT_THAT(resolution_error(140000.0, 10.0, 1),
              ::testing::HasSubstr("a substep moves an agent 0.5 (robots.speed * engine.dt over "
                                   "2 substeps)"));
}

TEST(Box2DEngine, WallsContainBodiesAndReportBumps) {
  const WorldSpec spec = box2d_world(40.0, 30.0, 40, Topology::Walls);
  const auto start = random_positions(spec, 40, 2.2, 31, 1.5);
  auto engine = make_box2d_engine(spec, start);
  auto headings = random_headings(40, 32);
  const std::vector<Signal> signals(40, kGo);
  int bumps_x = 0;
  int bumps_y = 0;
  for (int k = 0; k < 3000; ++k) {
    engine->step(moving(headings, 1.5, kAll), signals);
    const auto bumps = engine->reflections();
    for (std::size_t i = 0; i < headings.size(); ++i) {
      // What a controller does with the bumper bits.
      if (bumps[i] & ReflectedX) headings[i].x = -headings[i].x, ++bumps_x;
      if (bumps[i] & ReflectedY) headings[i].y = -headings[i].y, ++bumps_y;
      const Vec2 p = engine->positions()[i];
      ASSERT_GE(p.x, 1.0 - 0.02);
      ASSERT_LE(p.x, 40.0 - 1.0 + 0.02);
      ASSERT_GE(p.y, 1.0 - 0.02);
      ASSERT_LE(p.y, 30.0 - 1.0 + 0.02);
    }
  }
  EXPECT_GT(bumps_x, 20);
  EXPECT_GT(bumps_y, 20);
}

// A crowded arena where everyone pushes: bodies overlap by at most the relative travel of
// one substep when they first touch (Box2D has no speculative contacts) and are then
// pushed apart.
TEST(Box2DEngine, BodiesNeverOverlapMuch) {
  for (int substeps : {1, 4}) {
    WorldSpec spec = box2d_world(50.0, 50.0, 250);  // 31% of the area covered
    spec.engine.box2d.substeps = substeps;
    const auto start = random_positions(spec, 250, 2.0, 41);
    auto engine = make_box2d_engine(spec, start);
    const ArenaGeometry geometry = spec.arena.geometry();
    const auto commands = moving(random_headings(250, 42), 1.0, kAll);
    const std::vector<Signal> signals(250, kGo);
    double worst = INFINITY;
    for (int k = 0; k < 400; ++k) {
      engine->step(commands, signals);
      worst = std::min(worst, smallest_distance(geometry, engine->positions()));
    }
    // Relative travel per substep 0.2 / substeps, plus what a jam pushing from behind adds.
    EXPECT_GT(worst, 2.0 - 0.25 / substeps) << substeps << " substeps";
    std::printf("%d substeps: smallest centre distance in a jammed crowd %.4f (2r = 2)\n", substeps,
                worst);
  }
}

std::vector<Vec2> run_mixed_scenario(int steps) {
  const WorldSpec spec = box2d_world(60.0, 60.0, 150);
  const auto start = random_positions(spec, 150, 2.0, 51);
  const auto headings = random_headings(150, 52);
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> commands(150);
  std::vector<Signal> signals(150);
  std::vector<Vec2> trace;
  for (int k = 0; k < steps; ++k) {
    for (std::size_t i = 0; i < 150; ++i) {
      const auto role = static_cast<Signal>((i + static_cast<std::size_t>(k / 50)) % 3);
      signals[i] = role;
      MotionCommand& c = commands[i];
      c = MotionCommand{};
      if (role == kGo) {
        c.velocity = headings[i];
        c.halt_on = mask_of(kGo);
        c.blocked_by = mask_of(kWait);
      } else if (role == kLeave) {
        c.velocity = headings[i] * -1.0;
        c.blocked_by = mask_of(kWait);
        c.repelled_by = mask_of(kWait);
      }
    }
    engine->step(commands, signals);
    for (const Vec2& p : engine->positions()) trace.push_back(p);
  }
  return trace;
}

TEST(Box2DEngine, DeterministicInAnyThread) {
  const auto reference = run_mixed_scenario(400);
  std::vector<Vec2> a;
  std::vector<Vec2> b;
  std::thread ta([&] { a = run_mixed_scenario(400); });
  std::thread tb([&] { b = run_mixed_scenario(400); });
  ta.join();
  tb.join();
  ASSERT_EQ(reference.size(), a.size());
  for (std::size_t k = 0; k < reference.size(); ++k) {
    ASSERT_EQ(reference[k], a[k]) << k;  // bit-identical
    ASSERT_EQ(reference[k], b[k]) << k;
  }
}

}  // namespace
}  // namespace swarmagg
