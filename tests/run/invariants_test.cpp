#include "run/invariants.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "geometry/arena_geometry.hpp"
#include "run/replicate.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;

constexpr AgentState kGo = AgentState::Go;
constexpr AgentState kWait = AgentState::Wait;
constexpr AgentState kLeave = AgentState::Leave;

// A hand-made replicate state: agents where the test puts them, perception and aggregates
// derived from them as the engine and the tracker would.
struct Scene {
  WorldSpec spec;
  std::vector<Vec2> positions;
  NeighbourLists neighbours;
  SwarmState swarm;
  AggregateTracker aggregates;
  EventCounts events;
  ControllerRules rules;
  std::int64_t step = 1;
  std::optional<std::uint32_t> sleeper_due_to_move;  // what the engine's sleep check found
  std::vector<MotionCommand> commands;  // blocked_by as the Bayindir controller sets it
  std::vector<Signal> signals;

  // The world is a 40 x 40 torus with the defaults docs/reference/world-keys.md gives, changed by
  // `overrides`.
  Scene(const std::vector<std::string>& overrides, std::vector<Vec2> at,
        std::vector<AgentState> states)
      : spec(load_world_text("arena: {width: 40, height: 40}\nrobots: {count: 3}\n", "scene.yaml",
                             overrides)),
        positions(std::move(at)) {
    spec.robots.count = static_cast<int>(positions.size());
    swarm.resize(positions.size());
    swarm.state.assign(states.begin(), states.end());
    perceive();
  }

  void perceive() {
    const ArenaGeometry geometry = spec.arena.geometry();
    std::vector<ClosePair> pairs;
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
      for (std::uint32_t j = i + 1; j < positions.size(); ++j) {
        const Vec2 d = geometry.displacement(positions[i], positions[j]);
        if (norm(d) <= spec.sensing_radius()) pairs.push_back({i, j, d, norm(d)});
      }
    }
    neighbours.assign_from_pairs(positions.size(), pairs);
    rules = controller_rules(spec);
    signals.resize(positions.size());
    write_signals(swarm.state, signals);
    commands.assign(positions.size(), MotionCommand{});
    const auto mask = [](AgentState s) { return mask_of(static_cast<Signal>(s)); };
    const SignalMask searching = mask(kGo) | mask(AgentState::Approach);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const AgentState s = swarm.state[i];
      commands[i].blocked_by = s == kWait
                                   ? mask(kWait) | mask(kLeave) | (rules.joins ? searching : 0)
                               : s == kLeave ? mask(kWait)
                                             : (rules.joins ? mask(kWait) : 0);
    }
    aggregates.update(
        neighbours, swarm, spec.robots.detection_radius,
        rules.partners_only ? AggregateLinks::PartnersOnly : AggregateLinks::Proximity);
  }

  CheckedState state() const {
    return {spec,       rules,  3,          step,   positions,
            neighbours, swarm,  aggregates, events, sleeper_due_to_move,
            commands,   signals};
  }
};

// Three agents: a waiting pair (a creation) and one searcher far away.
Scene pair_and_searcher(const std::vector<std::string>& overrides = {}) {
  Scene scene(overrides, {{10, 10}, {13, 10}, {30, 30}}, {kWait, kWait, kGo});
  scene.events.creations = 1;
  return scene;
}

std::string violation(InvariantChecker& checker, const Scene& scene) {
  try {
    checker.check(scene.state());
  } catch (const InvariantViolation& e) {
    return e.what();
  }
  return "none";
}

std::string violation(const Scene& scene) {
  InvariantChecker checker;
  return violation(checker, scene);
}

TEST(Invariants, AConsistentStatePasses) {
  EXPECT_EQ(violation(pair_and_searcher()), "none");
}

TEST(Invariants, AMessageNamesTheReplicateStepAgentAndValues) {
  Scene scene = pair_and_searcher();
  scene.step = 12;
  scene.positions[2] = {std::nan(""), 5.0};
  EXPECT_EQ(violation(scene),
            "invariant violated in replicate 3 at step 12: agent 2 (GO) has a non-finite "
            "position (nan, 5)");
}

TEST(Invariants, PositionsMustLieInsideTheArena) {
  Scene torus = pair_and_searcher();
  torus.positions[2] = {41.0, 30.0};
  EXPECT_THAT(violation(torus), HasSubstr("agent 2 (GO) at (41, 30) is outside the 40 x 40"));
  // Walls keep a centre a body radius from each wall.
  Scene walls = pair_and_searcher({"arena.topology=walls"});
  EXPECT_EQ(violation(walls), "none");
  walls.positions[2] = {39.5, 30.0};
  EXPECT_THAT(violation(walls), HasSubstr("agent 2 (GO) at (39.5, 30) is outside"));
}

TEST(Invariants, NoAgentSleepsThatTheFullStepMoves) {
  Scene scene = pair_and_searcher();
  scene.sleeper_due_to_move = 1;
  EXPECT_THAT(violation(scene), HasSubstr("agent 1 slept, but the step resolved in full moves it"));
}

TEST(Invariants, EveryPartHoldsEveryAgent) {
  Scene scene = pair_and_searcher();
  scene.spec.robots.count = 4;
  EXPECT_THAT(violation(scene), HasSubstr("the engine holds 3 agents, the world 4"));
}

TEST(Invariants, HeadingsAreUnitVectors) {
  Scene scene = pair_and_searcher();
  scene.swarm.heading[2] = {0.5, 0.0};
  EXPECT_THAT(violation(scene), HasSubstr("agent 2 (GO) has heading (0.5, 0), not a unit vector"));
  scene.swarm.heading[2] = {std::numeric_limits<double>::infinity(), 0.0};
  EXPECT_THAT(violation(scene), HasSubstr("not a unit vector"));
}

TEST(Invariants, StatesMustBeOnesTheRulesEnter) {
  Scene bayindir = pair_and_searcher();
  bayindir.swarm.state[2] = AgentState::Approach;
  EXPECT_THAT(violation(bayindir), HasSubstr("agent 2 (APPROACH) is in a state this world's"));
  Scene no_leaving = pair_and_searcher({"controller.leave=false"});
  no_leaving.swarm.state[2] = kLeave;
  EXPECT_THAT(violation(no_leaving), HasSubstr("agent 2 (LEAVE) is in a state"));
  Scene corrupt = pair_and_searcher();
  corrupt.swarm.state[2] = static_cast<AgentState>(7);
  EXPECT_THAT(violation(corrupt), HasSubstr("agent 2 (state 7) has no valid state"));
}

TEST(Invariants, LeaveTimersStayWithinTheTimeout) {
  Scene scene = pair_and_searcher();
  scene.swarm.state[2] = kLeave;
  scene.swarm.leave_time_left[2] = 10.0;
  EXPECT_EQ(violation(scene), "none");
  scene.swarm.leave_time_left[2] = 10.5;
  EXPECT_THAT(violation(scene), HasSubstr("has 10.5 tu of LEAVE left, outside [0, leave_timeout"));
}

TEST(Invariants, OnlyWaitingAgentsAreInAggregates) {
  Scene scene = pair_and_searcher();
  scene.swarm.state[1] = kGo;  // the tracker still has it in the pair
  EXPECT_THAT(violation(scene), HasSubstr("agent 1 (GO) is labelled with aggregate 0 of 1"));
}

TEST(Invariants, LinkedWaitingAgentsShareAnAggregate) {
  Scene scene = pair_and_searcher();
  scene.swarm.state[2] = kWait;
  scene.positions[2] = {16, 10};  // within s of agent 1, but the tracker has not seen it
  scene.events.growths = 1;
  scene.neighbours.assign_from_pairs(
      3, std::vector<ClosePair>{{0, 1, {3, 0}, 3.0}, {1, 2, {3, 0}, 3.0}});
  EXPECT_THAT(violation(scene), HasSubstr("agent 1 (WAIT) and agent 2 (WAIT) are linked but in "
                                          "aggregates 0 and -1"));
  scene.perceive();
  EXPECT_EQ(violation(scene), "none");
}

TEST(Invariants, EventsAccountForTheWaitingAgents) {
  Scene scene = pair_and_searcher();
  scene.events.creations = 0;
  EXPECT_THAT(violation(scene), HasSubstr("do not account for the waiting agents"));
  scene.events = {2, 0, 2, 0, 0};  // 4 agents entered WAIT, 2 left it
  EXPECT_EQ(violation(scene), "none");
  scene.events.shrinks = 1;
  EXPECT_THAT(violation(scene), HasSubstr("(creations 2, growths 0, dissipations 2, shrinks 1, "
                                          "waiting 2)"));
}

TEST(Invariants, RulesSwitchEventsOff) {
  Scene no_join = pair_and_searcher({"controller.join=false"});
  no_join.swarm.partner = {1, 0, kNoPartner};
  no_join.perceive();
  EXPECT_EQ(violation(no_join), "none");
  no_join.events.growths = 1;
  EXPECT_THAT(violation(no_join), HasSubstr("events counted that the rules rule out"));
  Scene ghost = pair_and_searcher({"controller.type=collision", "controller.collision_mode=ghost"});
  ghost.swarm.state = {kGo, kGo, kGo};
  ghost.perceive();
  EXPECT_THAT(violation(ghost), HasSubstr("events counted that the rules rule out"));
}

TEST(Invariants, PartnerLinksMakeOnlyPairs) {
  Scene scene({"controller.join=false"}, {{10, 10}, {13, 10}, {16, 10}}, {kWait, kWait, kWait});
  scene.swarm.partner = {1, 2, 1};  // three agents linked through partners: impossible
  scene.events.creations = 2;
  scene.perceive();
  EXPECT_THAT(violation(scene), HasSubstr("aggregate 0 has size 3"));
}

TEST(Invariants, CumulativeEventsNeverDecrease) {
  InvariantChecker checker;
  Scene scene = pair_and_searcher();
  scene.events.encounters = 5;
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 2;
  scene.events.encounters = 4;
  EXPECT_THAT(violation(checker, scene),
              HasSubstr("at step 2: a cumulative event count decreased"));
}

TEST(Invariants, KinematicAgentsMoveAtMostVdtAndWaitingOnesNotAtAll) {
  InvariantChecker checker;
  Scene scene = pair_and_searcher({"controller.compaction.enabled=false"});
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 2;
  scene.positions[2] = {30.0625, 30};  // v dt = 0.1
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 3;
  scene.positions[2] = {30.25, 30};
  EXPECT_THAT(violation(checker, scene),
              HasSubstr("agent 2 (GO) moved 0.1875 from (30.0625, 30) to (30.25, 30) in one step; "
                        "at most 0.1 allowed"));
  checker.forget();
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 4;
  scene.positions[0] = {10, 10.0625};
  EXPECT_THAT(violation(checker, scene), HasSubstr("agent 0 (WAIT) moved 0.0625"));
}

// With compaction (docs/controllers.md) waiting agents close up, at most at v like everyone else.
TEST(Invariants, CompactingWaitingAgentsMoveAtMostVdt) {
  InvariantChecker checker;
  Scene scene = pair_and_searcher();
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 2;
  scene.positions[0] = {10.0625, 10};
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 3;
  scene.positions[0] = {10.25, 10};
  EXPECT_THAT(violation(checker, scene), HasSubstr("agent 0 (WAIT) moved 0.1875"));
}

TEST(Invariants, MotionAcrossTheSeamIsTheShortWayRound) {
  InvariantChecker checker;
  Scene scene = pair_and_searcher();
  scene.positions[2] = {39.95, 30};
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 2;
  scene.positions[2] = {0.05, 30};
  EXPECT_EQ(violation(checker, scene), "none");
}

TEST(Invariants, StepsThatDoNotFollowEachOtherAreNotCompared) {
  InvariantChecker checker;
  Scene scene = pair_and_searcher();
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 3;  // step 2 was not checked
  scene.positions[2] = {35, 30};
  EXPECT_EQ(violation(checker, scene), "none");
}

// A leaver driven from 2.5 to 0.75 from a waiting body's centre: the two are solid to
// each other.
// `solid`: as the Bayindir controller's masks say; else a controller whose masks let waiting
// and leaving bodies pass through each other (neither names the other's signal).
std::string sink_leaver(std::vector<std::string> overrides, bool solid = true) {
  overrides.push_back("robots.speed=20");
  InvariantChecker checker;
  Scene scene(overrides, {{10, 10}, {12.5, 10}}, {kWait, kLeave});
  scene.swarm.leave_time_left[1] = 5.0;
  scene.events = {1, 0, 1, 0, 0};  // the pair formed, then one left
  const std::string before = violation(checker, scene);
  if (before != "none") return "before: " + before;
  scene.step = 2;
  scene.positions[1] = {10.75, 10};
  scene.perceive();
  if (!solid) {
    scene.commands[0].blocked_by = mask_of(static_cast<Signal>(kWait));
    scene.commands[1].blocked_by = 0;
  }
  return violation(checker, scene);
}

TEST(Invariants, SolidBodiesDoNotSinkIntoEachOther) {
  EXPECT_THAT(sink_leaver({}), HasSubstr("agent 0 (WAIT) and agent 1 (LEAVE) are solid to each "
                                         "other but sank 1.25 into each other: centres 2.5 then "
                                         "0.75 apart, contact at 2"));
  // Box2D may let bodies overlap by up to r before it resolves the contact.
  EXPECT_THAT(sink_leaver({"engine.type=box2d"}), HasSubstr("sank 1.25"));
  EXPECT_EQ(sink_leaver({"engine.type=box2d", "robots.radius=1.9"}), "none");
  // Solidity is the masks' (docs/controllers.md), not the states': a controller of one's own
  // may let waiting and leaving bodies pass through each other (--check refused it).
  EXPECT_EQ(sink_leaver({}, false), "none");
}

TEST(Invariants, BodiesThatIgnoreEachOtherMayOverlap) {
  // Without joining, a searcher passes over a waiting body (the paper's point particles).
  InvariantChecker checker;
  Scene scene({"controller.join=false", "robots.speed=20"}, {{10, 10}, {13, 10}, {12, 12.5}},
              {kWait, kWait, kGo});
  scene.swarm.partner = {1, 0, kNoPartner};
  scene.events.creations = 1;
  scene.perceive();
  ASSERT_EQ(violation(checker, scene), "none");
  scene.step = 2;
  scene.positions[2] = {12, 10.5};
  scene.perceive();
  EXPECT_EQ(violation(checker, scene), "none");
}

// Every world kind keeps every invariant over a real run (the checker follows each step).
// 60 agents on a 60 x 60 torus, changed by `overrides`.
WorldSpec dense_world(const std::vector<std::string>& overrides) {
  return load_world_text("arena: {width: 60, height: 60}\nrobots: {count: 60}\n", "run.yaml",
                         overrides);
}

void expect_run_keeps_invariants(const std::vector<std::string>& overrides, std::int64_t steps) {
  const WorldSpec spec = dense_world(overrides);
  Replicate replicate(spec, 0);
  InvariantChecker checker;
  for (std::int64_t k = 0; k < steps; ++k) {
    replicate.step();
    ASSERT_NO_THROW(checker.check(checked_state(replicate))) << "step " << k + 1;
  }
  const EventCounts& e = replicate.events();
  EXPECT_GT(e.creations + e.encounters, 0u) << "nothing happened: the run tests nothing";
}

const std::vector<std::string> kFullModel = {"controller.p_leave=0.01",
                                             "controller.leave_timeout=3"};

std::vector<std::string> with(std::vector<std::string> base, std::vector<std::string> more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

TEST(InvariantsInRuns, FullModelKinematicTorusAndWalls) {
  expect_run_keeps_invariants(kFullModel, 3000);
  // Compaction on (the default) between walls: bodies solid to others meet the walls inside
  // the guarded move. (Mirrored after it, unguarded, a waiting body once sank 0.005 u further
  // into a searcher it already overlapped, at step 1471 of this run.)
  expect_run_keeps_invariants(with(kFullModel, {"arena.topology=walls"}), 3000);
  // Halting at contacts as before sliding, and without compaction, between walls too.
  expect_run_keeps_invariants(with(kFullModel, {"arena.topology=walls", "engine.contact=stop",
                                                "controller.compaction.enabled=false"}),
                              3000);
}

TEST(InvariantsInRuns, CreationAndDissipationWithPartners) {
  expect_run_keeps_invariants({"controller.join=false", "controller.p_leave=0.01"}, 3000);
}

// Issue 10: under isolated_wait: stay a waiting agent once kept its partner after that
// partner left; when the partner paired again, partner links joined three agents into one
// aggregate (step 149 here) and a later leave counted as a shrink.
TEST(InvariantsInRuns, CreationAndDissipationWithPartnersWhoStay) {
  expect_run_keeps_invariants(
      {"controller.join=false", "controller.p_leave=0.01", "controller.isolated_wait=stay"}, 3000);
}

TEST(InvariantsInRuns, SoysalWithApproach) {
  expect_run_keeps_invariants(
      {"controller.type=soysal", "controller.p0=0.01", "controller.leave_law=inverse"}, 3000);
}

TEST(InvariantsInRuns, CollisionPaperAndGhost) {
  expect_run_keeps_invariants({"controller.type=collision", "controller.collision_mode=paper"},
                              2000);
  expect_run_keeps_invariants({"controller.type=collision", "controller.tumble=0.01"}, 2000);
}

TEST(InvariantsInRuns, FullModelBox2DTorusAndWalls) {
  expect_run_keeps_invariants(with(kFullModel, {"engine.type=box2d"}), 1500);
  expect_run_keeps_invariants(with(kFullModel, {"engine.type=box2d", "arena.topology=walls"}),
                              1500);
}

TEST(InvariantsInRuns, CheckModeRunsTheChecksThroughTheReplicateHook) {
  const WorldSpec spec = dense_world({"run.duration=50", "run.replicates=3"});
  RunOptions options;
  options.threads = 2;
  options.check = true;
  EXPECT_NO_THROW(run_world(spec, options));
}

TEST(InvariantsInRuns, InterleavedReplicatesOnOneThreadAreNotConfused) {
  const WorldSpec spec = dense_world({});
  Replicate a(spec, 0);
  Replicate b(spec, 1);
  for (int k = 0; k < 200; ++k) {
    a.step();
    ASSERT_NO_THROW(check_invariants(a));
    b.step();
    ASSERT_NO_THROW(check_invariants(b));
  }
}

}  // namespace
}  // namespace swarmagg
