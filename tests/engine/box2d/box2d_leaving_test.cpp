// "Only peripheral agents can get out of an aggregate" must emerge from the Box2D engine's
// real contacts and the repulsion of waiting agents (docs/architecture.md), with the controllers
// unchanged: a LEAVE agent in the middle of a packed aggregate cannot get out within its timeout,
// one on the rim can.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "config/world_loader.hpp"
#include "controllers/controller.hpp"
#include "core/agent_state.hpp"
#include "engine/box2d/box2d_test_support.hpp"
#include "observers/aggregate_tracker.hpp"
#include "run/replicate.hpp"
#include "testing/forced_leave.hpp"

namespace swarmagg {
namespace {

using namespace swarmagg::testing;

constexpr double kCentre = 50.0;
constexpr double kSpacing = 2.05;  // nearly touching discs (2r = 2)

// A hexagonal aggregate of `rings` rings around (50, 50): 1 + 3 rings (rings + 1) agents.
std::vector<Vec2> hexagon(int rings) {
  std::vector<Vec2> out;
  for (int q = -rings; q <= rings; ++q) {
    for (int r = -rings; r <= rings; ++r) {
      if (std::abs(q + r) > rings) continue;
      out.push_back({kCentre + kSpacing * (q + 0.5 * r), kCentre + kSpacing * (0.8660254 * r)});
    }
  }
  return out;
}

std::string packed_world_yaml(int rings, double p_leave) {
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "name: packed-aggregate\n"
       << "arena: {width: 100, height: 100, topology: torus}\n"
       << "robots:\n  placement: [";
  const auto positions = hexagon(rings);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    yaml << (i ? ", " : "") << "[" << positions[i].x << ", " << positions[i].y << ", 0]";
  }
  yaml << "]\n"
       << "controller: {type: bayindir, p_leave: " << p_leave
       << ", leave_timeout: 10, join: true, leave: true, isolated_wait: stay}\n"
       << "engine: {type: box2d, dt: 0.1}\n"
       << "run: {duration: 1000, seed: 7}\n";
  return yaml.str();
}

// Whether the agent still perceived a waiting agent when its timeout ran out, sent to LEAVE
// by hand once the aggregate has formed (it then joins again: it did not get out).
bool caught_at_timeout(const WorldSpec& spec, AgentId leaver) {
  std::vector<Vec2> positions;
  for (const PlacedAgent& a : spec.robots.placement) positions.push_back({a.x, a.y});
  return testing::caught_at_timeout(spec, positions, leaver, spec.run.seed, 5);
}

TEST(Box2DLeaving, OnlyRimAgentsGetOutWithinTheTimeout) {
  const WorldSpec spec = load_world_text(packed_world_yaml(3, 0.0), "packed-aggregate");
  ASSERT_EQ(spec.robots.count, 37);
  // Agent 18 is the centre; 0, 3, 33 and 36 are corners of the outer ring; 1 is on an edge.
  EXPECT_TRUE(caught_at_timeout(spec, 18)) << "the central agent got out";
  for (AgentId rim : {0u, 1u, 3u, 33u, 36u}) {
    EXPECT_FALSE(caught_at_timeout(spec, rim)) << "rim agent " << rim << " was held back";
  }
}

struct LeaveTally {
  int inner = 0;  // leaves that started deep inside an aggregate
  int inner_caught = 0;
  int rim = 0;  // leaves that started on its rim, with the way out open
  int rim_caught = 0;
};

// What each agent perceives before a decision: waiting agents within s, the widest angle
// free of them, and whether the controller's escape direction (away from the sum of the
// offsets to everyone within s) is clear of them by 60 degrees.
struct Surroundings {
  int waiting = 0;
  double widest_gap = 360.0;
  bool way_open = false;
};

Surroundings surroundings(const NeighbourLists& neighbours, std::span<const AgentState> states,
                          AgentId agent, double s) {
  Surroundings out;
  std::vector<double> angles;
  Vec2 towards;
  for (const Neighbour& nb : neighbours.of(agent)) {
    if (nb.distance > s) continue;
    towards += nb.offset;
    if (states[nb.id] != AgentState::Wait) continue;
    ++out.waiting;
    angles.push_back(std::atan2(nb.offset.y, nb.offset.x) * 180.0 / kPi);
  }
  std::sort(angles.begin(), angles.end());
  if (angles.size() >= 2) {
    out.widest_gap = angles.front() + 360.0 - angles.back();
    for (std::size_t a = 1; a < angles.size(); ++a) {
      out.widest_gap = std::max(out.widest_gap, angles[a] - angles[a - 1]);
    }
  }
  if (norm(towards) > 1e-9) {
    const Vec2 away = towards * (-1.0 / norm(towards));
    out.way_open = true;
    for (const Neighbour& nb : neighbours.of(agent)) {
      if (nb.distance > s || states[nb.id] != AgentState::Wait) continue;
      if (dot(nb.offset, away) > 0.5 * nb.distance) out.way_open = false;
    }
  }
  return out;
}

// Runs replicates of the world and classifies every leave by where it started: inside
// (surrounded: no gap of 100 degrees between waiting neighbours) or on the rim (at least 3
// waiting neighbours, escape direction open); a leave is caught when, as its timeout runs
// out, a waiting agent is within s (the agent then joins again).
LeaveTally tally_leaves(const WorldSpec& spec, int replicates, int steps) {
  const auto n = static_cast<std::size_t>(spec.robots.count);
  const double s = spec.robots.detection_radius;
  LeaveTally tally;
  for (int index = 0; index < replicates; ++index) {
    Replicate replicate(spec, index);
    std::vector<std::uint8_t> inside(n, 0);
    std::vector<std::uint8_t> on_rim(n, 0);
    std::vector<Surroundings> around(n);
    AgentArray<AgentState> previous = replicate.swarm().state;
    for (int k = 0; k < steps; ++k) {
      for (std::size_t i = 0; i < n; ++i) {
        around[i] =
            surroundings(replicate.engine().neighbours(), previous, static_cast<AgentId>(i), s);
      }
      replicate.step();  // decides on the surroundings above, then moves
      const SwarmState& swarm = replicate.swarm();
      for (std::size_t i = 0; i < n; ++i) {
        if (previous[i] == AgentState::Wait && swarm.state[i] == AgentState::Leave) {
          inside[i] = around[i].widest_gap < 100.0;
          on_rim[i] = around[i].waiting >= 3 && around[i].way_open;
        }
        if (previous[i] == AgentState::Leave && swarm.state[i] != AgentState::Leave) {
          const bool caught = around[i].waiting > 0;
          if (inside[i]) {
            ++tally.inner;
            tally.inner_caught += caught ? 1 : 0;
          } else if (on_rim[i]) {
            ++tally.rim;
            tally.rim_caught += caught ? 1 : 0;
          }
        }
      }
      previous = swarm.state;
    }
  }
  return tally;
}

// The same through the full replicate, with leaving left to the controller (p = 0.0005 per
// step in a packed aggregate of 61): leaves that start deep inside mostly end their timeout
// next to waiting agents and join again; those that start on the rim mostly get away.
TEST(Box2DLeaving, ReplicateInnerLeaversAreCaughtRimLeaversEscape) {
  const WorldSpec spec = load_world_text(packed_world_yaml(4, 0.0005), "packed-aggregate");
  const LeaveTally t = tally_leaves(spec, 4, 3000);
  std::printf("inner leavers caught %d of %d, rim leavers caught %d of %d\n", t.inner_caught,
              t.inner, t.rim_caught, t.rim);
  ASSERT_GE(t.inner, 15);
  ASSERT_GE(t.rim, 15);
  // Not all or nothing: the controller re-aims a leaver every step away from the sum of the
  // offsets to what it perceives, which can send a rim agent into its nearest neighbour once
  // a far one drops out of range; and the aggregate loosens as agents come and go.
  const double inner_rate = static_cast<double>(t.inner_caught) / t.inner;
  const double rim_rate = static_cast<double>(t.rim_caught) / t.rim;
  EXPECT_GE(inner_rate, 0.65);
  EXPECT_LE(rim_rate, 0.35);
  EXPECT_GE(inner_rate - rim_rate, 0.4);
}

// A repulsion gain validation lets through (it bounds the push of one waiting body) can still
// push a leaver among several faster than Box2D's substeps allow: the run stops naming the
// replicate, the step and the agent, so that it can be found again.
TEST(Box2DLeaving, APushTooStrongForTheSubstepsNamesWhereItHappened) {
  const WorldSpec spec = load_world("worlds/examples/compact.yaml",
                                    {"engine.type=box2d", "engine.box2d.repulsion_gain=4e5",
                                     "robots.count=100", "arena.width=50", "arena.height=50"});
  Replicate replicate(spec, 0);
  std::string message;
  for (int step = 0; step < 600 && message.empty(); ++step) {
    try {
      replicate.step();
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
  }
  EXPECT_THAT(
      message,
      ::testing::MatchesRegex(
          "replicate 0, moving from step [0-9]+ to [0-9]+: Box2D engine: the repulsion push on "
          "leaving agent [0-9]+ reaches .*lower engine.box2d.repulsion_gain.*"));
}

}  // namespace
}  // namespace swarmagg
