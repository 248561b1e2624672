// The torus seam of the Box2D engine: sensing and collisions across an edge behave exactly as
// in mid-arena (docs/architecture.md: naive ghosts act like walls of infinite mass).
#include <gtest/gtest.h>

#include <vector>

#include "engine/box2d/box2d_test_support.hpp"

namespace swarmagg {
namespace {

using namespace swarmagg::testing;

struct ScenarioRun {
  std::vector<std::vector<Vec2>> displacement;  // [step][agent], accumulated minimum images
  std::vector<std::vector<double>> distance01;  // [step] distance agent 0 - agent 1
  std::vector<bool> perceived01;                // [step] agent 1 in agent 0's neighbours
  std::uint64_t encounters = 0;
};

// Places agent i at centre + offsets[i] (wrapped) and runs `steps` steps of fixed commands.
ScenarioRun run_scenario(const WorldSpec& spec, Vec2 centre, const std::vector<Vec2>& offsets,
                         const std::vector<MotionCommand>& commands,
                         const std::vector<Signal>& signals, int steps) {
  const ArenaGeometry geometry = spec.arena.geometry();
  std::vector<Vec2> start;
  for (const Vec2& o : offsets) start.push_back(geometry.wrap(centre + o));
  auto engine = make_box2d_engine(spec, start);
  ScenarioRun run;
  std::vector<Vec2> disp(offsets.size());
  std::vector<Vec2> last(start);
  for (int k = 0; k < steps; ++k) {
    run.encounters += engine->step(commands, signals).encounters;
    const auto p = engine->positions();
    for (std::size_t i = 0; i < p.size(); ++i) {
      EXPECT_GE(p[i].x, 0.0);
      EXPECT_LT(p[i].x, spec.arena.width);
      EXPECT_GE(p[i].y, 0.0);
      EXPECT_LT(p[i].y, spec.arena.height);
      disp[i] += geometry.displacement(last[i], p[i]);
      last[i] = p[i];
    }
    run.displacement.push_back(disp);
    run.distance01.push_back({geometry.distance(p[0], p[1])});
    bool seen = false;
    for (const Neighbour& n : engine->neighbours().of(0)) {
      if (n.id != 1) continue;
      seen = true;
      EXPECT_NEAR(n.distance, geometry.distance(p[0], p[1]), 1e-9);
      const Vec2 d = geometry.displacement(p[0], p[1]);
      EXPECT_NEAR(n.offset.x, d.x, 1e-9);
      EXPECT_NEAR(n.offset.y, d.y, 1e-9);
    }
    run.perceived01.push_back(seen);
  }
  return run;
}

void expect_same_motion(const ScenarioRun& a, const ScenarioRun& b, double tolerance) {
  ASSERT_EQ(a.displacement.size(), b.displacement.size());
  for (std::size_t k = 0; k < a.displacement.size(); ++k) {
    for (std::size_t i = 0; i < a.displacement[k].size(); ++i) {
      ASSERT_NEAR(a.displacement[k][i].x, b.displacement[k][i].x, tolerance)
          << "step " << k << " agent " << i;
      ASSERT_NEAR(a.displacement[k][i].y, b.displacement[k][i].y, tolerance)
          << "step " << k << " agent " << i;
    }
    ASSERT_EQ(a.perceived01[k], b.perceived01[k]) << "step " << k;
  }
  EXPECT_EQ(a.encounters, b.encounters);
}

// Box2D computes in float: mid-arena coordinates (~50) carry rounding errors of ~4e-6 that
// contact resolution amplifies a little. A ghost of infinite mass would differ by O(1).
constexpr double kFloatTolerance = 5e-4;

MotionCommand solid_move(Vec2 velocity) {
  MotionCommand c;
  c.velocity = velocity;
  c.blocked_by = kAll;
  return c;
}

struct SeamCase {
  const char* name;
  Vec2 centre;
};

class SeamTest : public ::testing::TestWithParam<SeamCase> {};

// Two agents approach head-on through the seam: they perceive each other at s, collide at 2r
// (instead of passing through each other) and end up pressed together, exactly as mid-arena.
TEST_P(SeamTest, HeadOnCollisionAcrossSeamMatchesMidArena) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const Vec2 dir = GetParam().centre.x == 0.0 && GetParam().centre.y == 0.0
                       ? Vec2{std::sqrt(0.5), std::sqrt(0.5)}
                       : (GetParam().centre.x == 0.0 ? Vec2{1.0, 0.0} : Vec2{0.0, 1.0});
  const std::vector<Vec2> offsets{dir * 4.05, dir * -4.05};
  const std::vector<MotionCommand> commands{solid_move(dir * -1.0), solid_move(dir * 1.0)};
  const std::vector<Signal> signals{kGo, kGo};
  const int steps = 60;
  const ScenarioRun seam = run_scenario(spec, GetParam().centre, offsets, commands, signals, steps);
  const ScenarioRun mid = run_scenario(spec, {50.0, 50.0}, offsets, commands, signals, steps);
  expect_same_motion(seam, mid, kFloatTolerance);

  EXPECT_EQ(seam.encounters, 1u);
  // 8.1 apart, closing at 2 u/tu: within s after 2.05 tu (step 21), in contact after 3.05 tu.
  EXPECT_FALSE(seam.perceived01[19]);
  EXPECT_TRUE(seam.perceived01[20]);
  for (std::size_t k = 0; k < seam.distance01.size(); ++k) {
    EXPECT_GT(seam.distance01[k][0], 2.0 - 0.2 - 1e-3) << "bodies sank into each other";
  }
  // Pressed together, not passed through: each moved 3.05 u towards the other, no more.
  EXPECT_NEAR(seam.distance01.back()[0], 2.0, 0.02);
  EXPECT_NEAR(dot(seam.displacement.back()[0], dir), -3.05, 0.02);
  EXPECT_NEAR(dot(seam.displacement.back()[1], dir), 3.05, 0.02);
}

// A moving agent hits a standing one off-centre through the seam: the standing one is pushed
// (it has a finite mass, unlike a naive ghost copy), exactly as mid-arena.
TEST_P(SeamTest, ObliquePushAcrossSeamMatchesMidArena) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const Vec2 dir = GetParam().centre.x == 0.0 && GetParam().centre.y == 0.0
                       ? Vec2{std::sqrt(0.5), std::sqrt(0.5)}
                       : (GetParam().centre.x == 0.0 ? Vec2{1.0, 0.0} : Vec2{0.0, 1.0});
  const Vec2 side{-dir.y, dir.x};
  const std::vector<Vec2> offsets{dir * 3.0 + side * 0.6, dir * -0.5};
  const std::vector<MotionCommand> commands{solid_move(dir * -1.0), solid_move({})};
  const std::vector<Signal> signals{kGo, kWait};
  const int steps = 80;
  const ScenarioRun seam = run_scenario(spec, GetParam().centre, offsets, commands, signals, steps);
  const ScenarioRun mid = run_scenario(spec, {50.0, 50.0}, offsets, commands, signals, steps);
  expect_same_motion(seam, mid, kFloatTolerance);
  // The standing agent was pushed along and sideways.
  EXPECT_LT(dot(seam.displacement.back()[1], dir), -0.5);
  EXPECT_LT(dot(seam.displacement.back()[1], side), -0.1);
}

// Without solidity the same pair passes through each other across the seam too, and the
// sensors still see each other and count one encounter.
TEST_P(SeamTest, GhostsPassThroughAcrossSeamAndAreSeen) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const Vec2 dir = GetParam().centre.x == 0.0 && GetParam().centre.y == 0.0
                       ? Vec2{std::sqrt(0.5), std::sqrt(0.5)}
                       : (GetParam().centre.x == 0.0 ? Vec2{1.0, 0.0} : Vec2{0.0, 1.0});
  const std::vector<Vec2> offsets{dir * 6.0, dir * -6.0};
  MotionCommand a, b;
  a.velocity = dir * -1.0;
  b.velocity = dir * 1.0;
  const ScenarioRun seam = run_scenario(spec, GetParam().centre, offsets, {a, b}, {kGo, kGo}, 120);
  const ScenarioRun mid = run_scenario(spec, {50.0, 50.0}, offsets, {a, b}, {kGo, kGo}, 120);
  expect_same_motion(seam, mid, kFloatTolerance);
  EXPECT_EQ(seam.encounters, 1u);
  EXPECT_NEAR(dot(seam.displacement.back()[0], dir), -12.0, 1e-3);
  // They were within s from t = 1 to 5 tu (distance 12 - 2t <= 4 <=> 4 <= t <= 8 ... ).
  int seen = 0;
  for (bool p : seam.perceived01) seen += p ? 1 : 0;
  EXPECT_NEAR(seen, 40, 1);  // 8 u of relative travel within s at 0.2 u per step
}

// A fast agent pushes a slow one along while both cross the seam: their contact survives the
// teleport of each body (which relabels the periodic images) and the pair moves as mid-arena.
TEST_P(SeamTest, PushingPairCrossesTheSeamAsMidArena) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const Vec2 dir = GetParam().centre.x == 0.0 && GetParam().centre.y == 0.0
                       ? Vec2{std::sqrt(0.5), std::sqrt(0.5)}
                       : (GetParam().centre.x == 0.0 ? Vec2{1.0, 0.0} : Vec2{0.0, 1.0});
  const std::vector<Vec2> offsets{dir * -5.25, dir * -3.0};
  const std::vector<MotionCommand> commands{solid_move(dir * 1.5), solid_move(dir * 0.5)};
  const std::vector<Signal> signals{kGo, kGo};
  const ScenarioRun seam = run_scenario(spec, GetParam().centre, offsets, commands, signals, 120);
  const ScenarioRun mid = run_scenario(spec, {40.0, 40.0}, offsets, commands, signals, 120);
  expect_same_motion(seam, mid, kFloatTolerance);
  // In contact from t = 0.25 tu on, moving together at (1.5 + 0.5) / 2 = 1 u/tu.
  EXPECT_NEAR(seam.distance01.back()[0], 2.0, 0.02);
  EXPECT_NEAR(dot(seam.displacement.back()[1], dir), 0.5 * 0.25 + 1.0 * (12.0 - 0.25), 0.05);
  EXPECT_GT(dot(seam.displacement.back()[1], dir), 6.0);  // crossed the seam
}

INSTANTIATE_TEST_SUITE_P(Seams, SeamTest,
                         ::testing::Values(SeamCase{"x", {0.0, 50.0}}, SeamCase{"y", {50.0, 0.0}},
                                           SeamCase{"corner", {0.0, 0.0}}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Box2DTorus, TeleportedBodyKeepsItsVelocity) {
  const WorldSpec spec = box2d_world(60.0, 40.0, 2);
  const std::vector<Vec2> start{{59.95, 39.97}, {30.0, 20.0}};
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> commands(2);
  commands[0].velocity = {1.0, 0.5};
  const std::vector<Signal> signals{kGo, kGo};
  Vec2 last = start[0];
  for (int k = 0; k < 30; ++k) {
    engine->step(commands, signals);
    const Vec2 p = engine->positions()[0];
    const ArenaGeometry geometry = spec.arena.geometry();
    const Vec2 moved = geometry.displacement(last, p);
    EXPECT_NEAR(moved.x, 0.1, 1e-5) << "step " << k;
    EXPECT_NEAR(moved.y, 0.05, 1e-5) << "step " << k;
    last = p;
  }
  EXPECT_NEAR(last.x, 59.95 + 3.0 - 60.0, 1e-4);
  EXPECT_NEAR(last.y, 39.97 + 1.5 - 40.0, 1e-4);
}

// Two agents travel side by side through the seam and its corner: they perceive each other at
// every step and the wrap never fakes an end and a new begin (no encounter).
TEST(Box2DTorus, WrapKeepsSensorContacts) {
  const WorldSpec spec = box2d_world(50.0, 50.0, 2);
  const std::vector<Vec2> start{{48.0, 47.0}, {45.5, 44.5}};
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> commands(2);
  commands[0].velocity = commands[1].velocity = {0.7, 0.7};
  const std::vector<Signal> signals{kGo, kGo};
  ASSERT_EQ(engine->neighbours().of(0).size(), 1u);
  std::uint64_t encounters = 0;
  for (int k = 0; k < 150; ++k) {
    encounters += engine->step(commands, signals).encounters;
    ASSERT_EQ(engine->neighbours().of(0).size(), 1u) << "step " << k;
    EXPECT_NEAR(engine->neighbours().of(0)[0].distance, std::hypot(2.5, 2.5), 1e-4);
  }
  EXPECT_EQ(encounters, 0u);
}

// Images never change an agent's mass or its centre: a body that had images at the seam and
// lost them in the interior responds to a force exactly as one that never had any.
TEST(Box2DTorus, ImagesLeaveTheMassAlone) {
  const WorldSpec spec = box2d_world(100.0, 100.0, 2);
  const std::vector<Vec2> start{{30.0, 50.0}, {99.0, 50.0}};
  auto engine = make_box2d_engine(spec, start);
  std::vector<MotionCommand> c(2);
  const std::vector<Signal> signals{kWait, kLeave};
  c[1].velocity = {1.0, 0.0};
  for (int k = 0; k < 285; ++k) engine->step(c, signals);  // through the seam to x = 27.5
  ASSERT_NEAR(engine->positions()[1].x, 27.5, 1e-3);
  c[1].velocity = {};
  c[1].repelled_by = mask_of(kWait);
  const double before = engine->positions()[1].x;
  engine->step(c, signals);
  // Force 20 (1 - 2.5/4) = 7.5 on a unit mass: 0.075 in one step, pointing away from x = 30.
  EXPECT_NEAR(engine->positions()[1].x - before, -0.075, 1e-4);
}

}  // namespace
}  // namespace swarmagg
