// Compaction (docs/controllers.md) on both engines, with the controllers unchanged: waiting agents
// close up to touching and hold a packed aggregate still; bodies never overlap; a leaver enclosed
// by its aggregate is held by the bodies around it, one on the rim gets out. No rule looks at
// where an agent stands, so the last two are what the engines' contacts make of the same
// commands.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "control_interface/state_signals.hpp"
#include "controllers/controller.hpp"
#include "geometry/arena_geometry.hpp"
#include "observers/aggregate_tracker.hpp"
#include "run/replicate.hpp"
#include "testing/forced_leave.hpp"

namespace swarmagg {
namespace {

constexpr double kCentre = 50.0;
constexpr double kRadius = 1.0;
constexpr double kSpacing = 2.0;  // the default: 2r, touching

// A hexagonal pack of 1 + 3 rings (rings + 1) agents around (50, 50), centres `spacing`
// apart; the centre first, then ring by ring (the 19-pack's rim is agents 7 to 18).
std::vector<Vec2> hexagon(int rings, double spacing) {
  std::vector<Vec2> out{{kCentre, kCentre}};
  for (int ring = 1; ring <= rings; ++ring) {
    for (int q = -ring; q <= ring; ++q) {
      for (int r = -ring; r <= ring; ++r) {
        if (std::max({std::abs(q), std::abs(r), std::abs(q + r)}) != ring) continue;
        out.push_back(
            {kCentre + spacing * (q + 0.5 * r), kCentre + spacing * 0.8660254037844386 * r});
      }
    }
  }
  return out;
}

WorldSpec placed_world(const std::vector<Vec2>& positions, EngineType engine, bool join = true) {
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "name: compaction\narena: {width: 100, height: 100, topology: torus}\n"
       << "robots:\n  placement: [";
  for (std::size_t i = 0; i < positions.size(); ++i) {
    yaml << (i ? ", " : "") << "[" << positions[i].x << ", " << positions[i].y << ", 0]";
  }
  yaml << "]\ncontroller: {type: bayindir, p_leave: 0, leave_timeout: 10, join: "
       << (join ? "true" : "false") << ", leave: true, isolated_wait: stay}\n"
       << "engine: {type: " << (engine == EngineType::Box2D ? "box2d" : "kinematic")
       << ", dt: 0.1}\nrun: {duration: 1000, seed: 7}\n";
  return load_world_text(yaml.str(), "compaction-test");
}

double smallest_distance(const WorldSpec& spec, std::span<const Vec2> p) {
  const ArenaGeometry geometry = spec.arena.geometry();
  double smallest = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      smallest = std::min(smallest, geometry.distance(p[i], p[j]));
    }
  }
  return smallest;
}

Vec2 centroid(std::span<const Vec2> p) {
  Vec2 sum;
  for (const Vec2& q : p) sum += q;
  return sum * (1.0 / static_cast<double>(p.size()));
}

// Bodies may touch, never sink into each other. The kinematic engine stops them at contact
// exactly (up to rounding). Box2D's contacts are real but soft: it finds a contact between
// two moving discs only once they overlap, so two bodies closing at up to 2 v overlap by up
// to 2 v dt = 0.2 u (one substep here) when they first touch, and its solver then pushes them
// apart over a few steps; 0.25 u allows that and a little solver give, an eighth of a
// diameter.
double overlap_allowed(EngineType engine) {
  return engine == EngineType::Box2D ? 0.25 : 1e-9;
}

std::string engine_name(EngineType engine) {
  return engine == EngineType::Box2D ? "box2d" : "kinematic";
}

class Compaction : public ::testing::TestWithParam<EngineType> {};

TEST_P(Compaction, APackedHexagonOfNineteenHoldsItsShapeForAThousandSteps) {
  const EngineType engine = GetParam();
  // A hair over 2r, so that rounding in the placement does not read as an overlap.
  const auto start = hexagon(2, kSpacing * (1.0 + 1e-9));
  ASSERT_EQ(start.size(), 19u);
  const WorldSpec spec = placed_world(start, engine);
  Replicate replicate(spec, 0);
  replicate.set_checking(true);
  const Vec2 centre = centroid(start);
  for (int step = 0; step < 1000; ++step) {
    replicate.step();
    const auto p = replicate.engine().positions();
    ASSERT_GE(smallest_distance(spec, p), 2.0 * kRadius - overlap_allowed(engine))
        << "step " << step;
    ASSERT_LT(norm(centroid(p) - centre), 0.1 * kRadius) << "step " << step;
  }
  for (const AgentState state : replicate.swarm().state) EXPECT_EQ(state, AgentState::Wait);
  EXPECT_EQ(replicate.aggregates().largest(), 19);
  // The shape: every agent within 0.1 r of where it started.
  const auto p = replicate.engine().positions();
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LT(norm(p[i] - start[i]), 0.1 * kRadius) << "agent " << i;
  }
}

// Two partners 3.5 apart (each perceives the other) close to the spacing: the gap shrinks by
// 2 gain dt of itself per step once below v / gain (1.5 at first, capped at v), so
// |d - 2| < 0.05 takes about ln(1.5 / 0.05) / 0.2 = 17 steps; 60 is generous, and
// the distance must then stay within the tolerance (each stands once its force is below it).
void expect_partners_close(EngineType engine, bool join) {
  const WorldSpec spec = placed_world({{48.25, 50.0}, {51.75, 50.0}}, engine, join);
  Replicate replicate(spec, 0);
  replicate.set_checking(true);
  const ArenaGeometry geometry = spec.arena.geometry();
  const double tolerance = spec.controller.compaction.tolerance;
  int settled_at = -1;
  for (int step = 0; step < 200; ++step) {
    replicate.step();
    const auto p = replicate.engine().positions();
    const double d = geometry.distance(p[0], p[1]);
    ASSERT_GE(d, 2.0 * kRadius - overlap_allowed(engine)) << "step " << step;
    if (settled_at < 0 && std::abs(d - kSpacing) <= tolerance) settled_at = step;
    if (settled_at >= 0) {
      EXPECT_LE(std::abs(d - kSpacing), tolerance) << "step " << step;
    }
  }
  ASSERT_GE(settled_at, 0) << engine_name(engine) << ": never closed up";
  EXPECT_LE(settled_at, 60) << engine_name(engine);
  EXPECT_EQ(replicate.swarm().state[0], AgentState::Wait);
  EXPECT_EQ(replicate.swarm().state[1], AgentState::Wait);
}

TEST_P(Compaction, TwoWaitingPartnersCloseToTheSpacingWithoutOverlap) {
  expect_partners_close(GetParam(), true);
}

TEST_P(Compaction, UnderJoinFalsePartnersCloseToTheSpacing) {
  expect_partners_close(GetParam(), false);
}

// Whether `leaver`, sent to LEAVE by hand after the pack has settled for 20 steps, escaped
// (docs/models.md): at the end of its timeout it perceived no waiting agent. No two bodies may come
// closer than contact allows on the way.
bool escapes(const WorldSpec& spec, const std::vector<Vec2>& start, AgentId leaver,
             std::uint64_t seed) {
  double closest = INFINITY;
  const bool caught =
      testing::caught_at_timeout(spec, start, leaver, seed, 20, [&](const Engine& e) {
        closest = std::min(closest, smallest_distance(spec, e.positions()));
      });
  EXPECT_GE(closest, 2.0 * kRadius - overlap_allowed(spec.engine.type));
  return !caught;
}

// The 19-pack of each trial: placed 2.3 apart (compaction closes it up in the 20 steps before
// the leave) with each centre moved by up to 0.1 along each axis at random (seeded), so that
// no two bodies overlap at the start and the packs, like real aggregates, are not perfect.
std::vector<Vec2> jittered_pack(std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Vec2> out;
  for (const Vec2& p : hexagon(2, 2.3)) {
    out.push_back({p.x + jitter(gen), p.y + jitter(gen)});
  }
  return out;
}

constexpr int kTrials = 100;

// A leaver at the centre of a packed 19-pack has six bodies around it, each pulled in by the
// rest of the pack; whatever heading it draws, it must not get out in any trial (it is the
// case docs/controllers.md says contacts alone must decide).
TEST_P(Compaction, AnEnclosedLeaverNeverGetsOut) {
  int escaped = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const auto start = jittered_pack(1000 + trial);
    const WorldSpec spec = placed_world(start, GetParam());
    escaped += escapes(spec, start, 0, 1000 + trial) ? 1 : 0;
  }
  EXPECT_EQ(escaped, 0) << engine_name(GetParam());
  std::cout << engine_name(GetParam()) << ": " << escaped << " of " << kTrials
            << " enclosed leavers got out\n";
}

// A rim agent (one of the twelve, by trial) heads away from the pack with nothing in its way.
// Both engines slide it along the rim neighbours it touches (Box2D by its contact solver, the
// kinematic engine by engine.contact: slide), so it should get out nearly always: 100 of 100
// measured on Box2D and 96 of 100 on the kinematic engine (91 before 2026-11-26, when a
// jammed neighbour could still hold a leaver, ALeaverBesideJammedMembersGetsOut), whose exact
// contacts hold a mid-edge leaver whose jittered heading presses it into the wedge between two
// neighbours. Both must reach 80, almost four binomial standard deviations (2.9 at p = 0.91)
// below the kinematic count. (Halting at contact,
// engine.contact: stop, let only 76 out: six of the twelve rim agents sit mid-edge with the
// neighbours they touch at right angles to their way out, and the jitter tilts that way into
// one of them about half the time.)
TEST_P(Compaction, ARimLeaverGetsOutInMostTrials) {
  int escaped = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const auto start = jittered_pack(2000 + trial);
    const WorldSpec spec = placed_world(start, GetParam());
    const auto rim = static_cast<AgentId>(7 + trial % 12);
    escaped += escapes(spec, start, rim, 2000 + trial) ? 1 : 0;
  }
  EXPECT_GE(escaped, 80) << engine_name(GetParam());
  std::cout << engine_name(GetParam()) << ": " << escaped << " of " << kTrials
            << " rim leavers got out\n";
}

// A rhombus of four: the two side agents touch both middle ones and pull each other in
// through them (about 3.46 apart, against a spacing of 2), straight into the wedge the middle
// pair makes: jammed, they press without moving. A middle one then leaves along the middle
// pair's axis, away from the others, with nothing in its way, and must get out in every
// trial (the side agents start at jittered places, so that they jam at slightly different
// contacts). Before the kinematic engine let a body pressed on by a contact go on when it
// presses into nothing itself (KinematicEngine.ABodyMovingAwayGoesOnWhileAJammedNeighbour-
// PressesIntoIt), 20 of these 40 leavers were halted at the start of every step and never
// moved. Box2D let all 40 out.
TEST_P(Compaction, ALeaverBesideJammedMembersGetsOut) {
  constexpr int kRhombi = 40;
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  int escaped = 0;
  for (int trial = 0; trial < kRhombi; ++trial) {
    const std::vector<Vec2> rhombus{{kCentre - 1.0, kCentre},
                                    {kCentre + 1.0, kCentre},
                                    {kCentre + jitter(gen), kCentre + 2.0 + std::abs(jitter(gen))},
                                    {kCentre + jitter(gen), kCentre - 2.0 - std::abs(jitter(gen))}};
    const WorldSpec spec = placed_world(rhombus, GetParam());
    escaped += escapes(spec, rhombus, 1, 3000 + trial) ? 1 : 0;
  }
  EXPECT_EQ(escaped, kRhombi) << engine_name(GetParam());
}

INSTANTIATE_TEST_SUITE_P(BothEngines, Compaction,
                         ::testing::Values(EngineType::Kinematic, EngineType::Box2D),
                         [](const auto& info) { return engine_name(info.param); });

}  // namespace
}  // namespace swarmagg
