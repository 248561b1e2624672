// The neighbour-count (cockroach) controller through the public harness: single decisions
// with ControllerFixture, whole runs on both engines with the scenario runner.
#include "controllers/cockroach/cockroach_controller.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "control_interface/state_signals.hpp"
#include "controller_testing/controller_fixture.hpp"
#include "controller_testing/scenario.hpp"
#include "core/errors.hpp"

namespace swarmagg {
namespace {

using testing::ControllerFixture;
using testing::run_scenario;
using testing::scenario_world;

WorldSpec cockroach(const std::string& stop, const std::string& leave) {
  return scenario_world("controller: {type: cockroach, stop_probability: " + stop +
                        ", leave_probability: " + leave + ", leave_timeout: 1}\n");
}

TEST(CockroachController, ASearcherStopsWithTheProbabilityOfItsWaitingNeighbourCount) {
  ControllerFixture f(cockroach("[0, 1]", "[0]"));  // n = 1: never; n >= 2: always
  f.add(10, 10, AgentState::Wait);
  f.add(12, 10, AgentState::Wait);
  const auto two = f.add(11, 13);  // perceives both waiting agents
  f.decide();
  EXPECT_EQ(f.swarm.state[two], AgentState::Wait);
  EXPECT_EQ(f.events.growths, 1u);
  EXPECT_EQ(f.events.creations, 0u);
}

TEST(CockroachController, AGrowthCountsAtTheSizeOfTheAggregateJoined) {
  ControllerFixture f(cockroach("[1]", "[0]"));
  f.add(10, 10, AgentState::Wait);
  f.add(12, 10, AgentState::Wait);
  f.add(11, 13);  // joins the pair
  f.decide();
  EXPECT_EQ(f.growths_by_size[2], 1u);
  EXPECT_EQ(f.events.growths, 1u);
}

TEST(CockroachController, ASearcherThatDoesNotStopWalksAwayFromTheWaitingAgents) {
  ControllerFixture f(cockroach("[0, 1]", "[0]"));
  f.add(10, 10, AgentState::Wait);
  f.add(10, 40, AgentState::Wait);
  const auto one = f.add(13, 10);  // perceives one waiting agent: p = 0
  f.decide();
  EXPECT_EQ(f.swarm.state[one], AgentState::Go);
  EXPECT_EQ(f.swarm.heading[one], (Vec2{1.0, 0.0}));
  EXPECT_EQ(f.commands[one].velocity, (Vec2{1.0, 0.0}));
  EXPECT_EQ(f.events.growths, 0u);
}

TEST(CockroachController, TheLastEntryHoldsForLargerCounts) {
  EXPECT_EQ(CockroachController::entry({0.1, 0.2}, 0), 0.1);
  EXPECT_EQ(CockroachController::entry({0.1, 0.2}, 1), 0.2);
  EXPECT_EQ(CockroachController::entry({0.1, 0.2}, 7), 0.2);
  ControllerFixture f(cockroach("[0, 1]", "[0]"));
  for (const double x : {10.0, 12.0, 14.0}) f.add(x, 10, AgentState::Wait);
  const auto three = f.add(12, 12.5);  // perceives three waiting agents
  f.decide();
  EXPECT_EQ(f.swarm.state[three], AgentState::Wait);
}

TEST(CockroachController, SearchersThatPerceiveNoWaitingAgentPairUp) {
  ControllerFixture f(cockroach("[0]", "[0]"));
  const auto a = f.add(10, 10);
  const auto b = f.add(13, 10);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.swarm.state[b], AgentState::Wait);
  EXPECT_EQ(f.events.creations, 1u);
}

TEST(CockroachController, AWaitingAgentLeavesWithTheProbabilityOfItsWaitingNeighbourCount) {
  ControllerFixture f(cockroach("[0]", "[0, 1, 0]"));  // leaves only when it perceives one
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Wait);
  const auto alone = f.add(50, 50, AgentState::Wait);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Leave);
  EXPECT_EQ(f.swarm.state[b], AgentState::Leave);
  EXPECT_EQ(f.swarm.state[alone], AgentState::Wait);
  EXPECT_EQ(f.events.dissipations, 1u);              // the pair dissolves once
  EXPECT_EQ(f.swarm.heading[a], (Vec2{-1.0, 0.0}));  // away from its partner
  EXPECT_EQ(f.swarm.leave_time_left[a], 1.0);
}

TEST(CockroachController, ALeaverSearchesAgainAfterItsTimeout) {
  ControllerFixture f(cockroach("[0]", "[0]"));
  const auto a = f.add(10, 10, AgentState::Leave);
  f.swarm.leave_time_left[a] = 0.1;
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Go);
}

// Compaction (docs/controllers.md) is on by default: a waiting agent that goes on waiting moves
// under the spring force of the waiting members of its aggregate it perceives, solid to every body.
TEST(CockroachController, WaitingMembersCloseUpUnderCompaction) {
  ControllerFixture f(cockroach("[0]", "[0]"));
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Wait);  // 3 apart: spring (3 - 2r) = 1, at v = 1
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.commands[a].velocity, (Vec2{1.0, 0.0}));
  EXPECT_EQ(f.commands[b].velocity, (Vec2{-1.0, 0.0}));
  const SignalMask solid = mask_of(signal_of(AgentState::Wait)) |
                           mask_of(signal_of(AgentState::Leave)) |
                           mask_of(signal_of(AgentState::Go));
  EXPECT_EQ(f.commands[a].blocked_by, solid);

  ControllerFixture off(scenario_world(
      "controller: {type: cockroach, stop_probability: [0], leave_probability: [0]}\n",
      {"controller.compaction.enabled=false"}));
  off.add(10, 10, AgentState::Wait);
  off.add(13, 10, AgentState::Wait);
  off.decide();
  EXPECT_EQ(off.commands[0].velocity, (Vec2{0.0, 0.0}));
  EXPECT_EQ(off.commands[0].blocked_by, mask_of(signal_of(AgentState::Wait)));
}

// A leaver whose neighbours surround it (their offsets nearly cancel) is enclosed: it draws a
// random heading (docs/controllers.md) instead of the direction of the small remainder.
TEST(CockroachController, AnEnclosedLeaverDrawsARandomHeading) {
  // Only an agent that perceives six waiting agents leaves: the centre of the ring.
  const auto leaver = [](bool compaction) {
    ControllerFixture f(scenario_world(
        "controller: {type: cockroach, stop_probability: [0], "
        "leave_probability: [0, 0, 0, 0, 0, 0, 1]}\n",
        {std::string("controller.compaction.enabled=") + (compaction ? "true" : "false")}));
    const auto centre = f.add(50, 50, AgentState::Wait);
    for (int k = 0; k < 6; ++k) {
      const double angle = k * 1.0471975511965976;
      const double d = k == 0 ? 2.2 : 2.1;  // slightly off-centre: the sum is not zero
      f.add(50 + d * std::cos(angle), 50 + d * std::sin(angle), AgentState::Wait);
    }
    f.decide();
    EXPECT_EQ(f.swarm.state[centre], AgentState::Leave);
    return f.swarm.heading[centre];
  };
  const Vec2 away = leaver(false);  // away from the nearer side
  EXPECT_NEAR(away.x, -1.0, 1e-9);
  EXPECT_NEAR(away.y, 0.0, 1e-9);
  EXPECT_EQ(leaver(true), random_heading(CounterRng(11), 0, 0, Draw::EnclosedLeave));
}

TEST(CockroachController, ListsMustHoldProbabilities) {
  const auto message = [](const std::string& key, const std::string& value) {
    try {
      scenario_world("controller: {type: cockroach, " + key + ": " + value + "}\n");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string expected = "expected a list of one or more numbers from 0 to 1";
  EXPECT_THAT(message("stop_probability", "[0.5, 1.5]"),
              ::testing::HasSubstr("controller.stop_probability: " + expected));
  EXPECT_THAT(message("leave_probability", "[]"),
              ::testing::HasSubstr("controller.leave_probability: " + expected));
  EXPECT_THAT(message("stop_probability", "0.5"), ::testing::HasSubstr(expected));
  EXPECT_THAT(message("stop_probability", "[-0.1]"), ::testing::HasSubstr(expected));
  // The item at fault is named, not just "a list".
  EXPECT_THAT(message("stop_probability", "[0.5, 1.5]"),
              ::testing::HasSubstr("got a list whose item 2 is '1.5'"));
  EXPECT_THAT(message("stop_probability", "[0.5, [1]]"),
              ::testing::HasSubstr("got a list whose item 2 is [1]"));
}

TEST(CockroachController, ItsKeysAreWrittenBackOnlyForItsWorlds) {
  const std::string written = world_to_yaml(cockroach("[0.25]", "[0.5, 0.125]"));
  EXPECT_THAT(written, ::testing::HasSubstr("stop_probability: [0.25]"));
  EXPECT_THAT(written, ::testing::HasSubstr("leave_probability: [0.5, 0.125]"));
  EXPECT_THAT(world_to_yaml(scenario_world("name: plain\n")),
              ::testing::Not(::testing::HasSubstr("stop_probability")));
  const WorldSpec again = scenario_world(written);
  EXPECT_EQ(world_to_yaml(again), written);
}

// The example world, shortened, on both engines: aggregates form and members leave, and
// every step keeps the invariants of the controller's rules.
class CockroachWorld : public ::testing::TestWithParam<const char*> {};

TEST_P(CockroachWorld, AggregatesFormAndMembersLeave) {
  const WorldSpec world =
      load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/cockroach.yaml",
                 {std::string("engine.type=") + GetParam()});
  const testing::ScenarioEnd end = run_scenario(world, 3000);
  EXPECT_GT(end.events.creations, 0u);
  EXPECT_GT(end.events.growths, 0u);
  EXPECT_GT(end.events.dissipations + end.events.shrinks, 0u);
  EXPECT_FALSE(end.aggregate_sizes.empty());
}

INSTANTIATE_TEST_SUITE_P(BothEngines, CockroachWorld, ::testing::Values("kinematic", "box2d"));

// A hexagon of seven agents 3 apart (within s, so one aggregate once all wait) on each engine,
// with the invariants checked every step. With compaction the members close up to touching
// (2r); without it they stand where they stopped.
class CockroachCompaction : public ::testing::TestWithParam<const char*> {};

std::vector<double> distances_to_centre(const testing::ScenarioEnd& end) {
  std::vector<double> out;
  for (std::size_t i = 1; i < end.positions.size(); ++i)
    out.push_back(norm(end.positions[i] - end.positions[0]));
  return out;
}

testing::ScenarioEnd hexagon_run(const char* engine, bool compaction) {
  std::ostringstream yaml;
  yaml.precision(17);
  yaml << "arena: {width: 60, height: 60, topology: torus}\nrobots:\n  placement: [[30, 30, 0]";
  for (int k = 0; k < 6; ++k) {
    const double angle = k * 1.0471975511965976;
    yaml << ", [" << 30 + 3 * std::cos(angle) << ", " << 30 + 3 * std::sin(angle) << ", 0]";
  }
  yaml << "]\ncontroller: {type: cockroach, stop_probability: [1], leave_probability: [0]}\n";
  const WorldSpec world = scenario_world(
      yaml.str(),
      {std::string("engine.type=") + engine,
       std::string("controller.compaction.enabled=") + (compaction ? "true" : "false")});
  return run_scenario(world, 300);
}

TEST_P(CockroachCompaction, WaitingMembersCloseUpToTouching) {
  const testing::ScenarioEnd end = hexagon_run(GetParam(), true);
  for (const AgentState state : end.states) EXPECT_EQ(state, AgentState::Wait);
  EXPECT_EQ(end.aggregate_sizes, std::vector<std::int32_t>{7});
  for (const double d : distances_to_centre(end)) {
    EXPECT_GT(d, 1.9) << GetParam();  // bodies do not overlap (Box2D: within its slop)
    EXPECT_LT(d, 2.2) << GetParam();  // from 3: closed up to about 2r
  }
}

TEST_P(CockroachCompaction, WithoutCompactionWaitingMembersStand) {
  const testing::ScenarioEnd end = hexagon_run(GetParam(), false);
  for (const AgentState state : end.states) EXPECT_EQ(state, AgentState::Wait);
  for (const double d : distances_to_centre(end)) EXPECT_GT(d, 2.8) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(BothEngines, CockroachCompaction, ::testing::Values("kinematic", "box2d"));

}  // namespace
}  // namespace swarmagg
