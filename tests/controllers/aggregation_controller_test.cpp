#include "controllers/aggregation_controller.hpp"

#include <gtest/gtest.h>

#include <bit>

#include "controller_testing/controller_fixture.hpp"

namespace swarmagg {
namespace {

using testing::ControllerFixture;

constexpr SignalMask kGoMask = mask_of(static_cast<Signal>(AgentState::Go));
constexpr SignalMask kWaitMask = mask_of(static_cast<Signal>(AgentState::Wait));

WorldSpec bayindir(bool join, bool leave, double p) {
  WorldSpec spec;
  spec.controller.type = "bayindir";
  spec.controller.join = join;
  spec.controller.leave = leave;
  spec.controller.p_leave = p;
  spec.controller.leave_timeout = 1.0;
  return spec;
}

TEST(BayindirController, TwoSearchersWithinSFormAPair) {
  ControllerFixture f(bayindir(true, true, 0.0));
  const auto a = f.add(10, 10);
  const auto b = f.add(13.5, 10);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.swarm.state[b], AgentState::Wait);
  EXPECT_EQ(f.swarm.partner[a], static_cast<std::int32_t>(b));
  EXPECT_EQ(f.events.creations, 1u);
  EXPECT_EQ(f.events.growths, 0u);
  EXPECT_EQ(f.commands[a].velocity, (Vec2{0.0, 0.0}));
}

TEST(BayindirController, ALoneSearcherGoesStraightGuardedByItsTargets) {
  ControllerFixture f(bayindir(true, true, 0.0));
  const auto a = f.add(10, 10);
  f.add(20, 10);  // 10 away: not perceived
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Go);
  EXPECT_EQ(f.commands[a].velocity, (Vec2{1.0, 0.0}));
  EXPECT_EQ(f.commands[a].halt_on & (kGoMask | kWaitMask), kGoMask | kWaitMask);
}

TEST(BayindirController, ASearcherJoinsAWaitingAgentWhenJoiningIsAllowed) {
  ControllerFixture f(bayindir(true, true, 0.0));
  f.add(10, 10, AgentState::Wait);
  f.add(13, 10, AgentState::Wait);
  const auto c = f.add(16.5, 10);
  f.decide();
  EXPECT_EQ(f.swarm.state[c], AgentState::Wait);
  EXPECT_EQ(f.events.growths, 1u);
  EXPECT_EQ(f.events.creations, 0u);
}

TEST(BayindirController, WithoutJoiningSearchersIgnoreWaitingAgents) {
  ControllerFixture f(bayindir(false, false, 0.0));
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Wait);
  f.swarm.partner[a] = static_cast<std::int32_t>(b);
  f.swarm.partner[b] = static_cast<std::int32_t>(a);
  const auto c = f.add(16.5, 10);
  f.decide();
  EXPECT_EQ(f.swarm.state[c], AgentState::Go);
  EXPECT_EQ(f.commands[c].halt_on & kWaitMask, 0u);
  EXPECT_EQ(f.commands[c].blocked_by & kWaitMask, 0u);  // passes over them
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
}

TEST(BayindirController, ThreeSearchersMeetingFormOnePairAndAGrowthWhenJoining) {
  ControllerFixture f(bayindir(true, true, 0.0));
  f.add(10, 10);
  f.add(13, 10);
  f.add(16.5, 10);
  f.decide();
  for (AgentState s : f.swarm.state) EXPECT_EQ(s, AgentState::Wait);
  EXPECT_EQ(f.events.creations, 1u);
  EXPECT_EQ(f.events.growths, 1u);
}

TEST(BayindirController, ThreeSearchersWithoutJoiningLeaveTheOddOneSearching) {
  ControllerFixture f(bayindir(false, false, 0.0));
  const auto a = f.add(10, 10);
  const auto b = f.add(13, 10);  // nearest pair: a-b (3 apart)
  const auto c = f.add(16.5, 10);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.swarm.state[b], AgentState::Wait);
  EXPECT_EQ(f.swarm.state[c], AgentState::Go);
  EXPECT_EQ(f.events.creations, 1u);
}

TEST(BayindirController, PairsAcrossTheSeamAreMutual) {
  ControllerFixture f(bayindir(false, false, 0.0));
  const auto a = f.add(99, 50);
  const auto b = f.add(2, 50);
  f.decide();
  EXPECT_EQ(f.swarm.partner[a], static_cast<std::int32_t>(b));
  EXPECT_EQ(f.swarm.partner[b], static_cast<std::int32_t>(a));
}

TEST(BayindirController, WaitingAgentsLeaveWithProbabilityOneAndCountDissipation) {
  ControllerFixture f(bayindir(true, true, 1.0));
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Wait);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Leave);
  EXPECT_EQ(f.swarm.state[b], AgentState::Leave);
  // Both members of one pair leaving in the same step dissolve it once.
  EXPECT_EQ(f.events.dissipations, 1u);
  // Each moves away from the other.
  EXPECT_LT(f.commands[a].velocity.x, 0.0);
  EXPECT_GT(f.commands[b].velocity.x, 0.0);
  EXPECT_EQ(f.commands[a].blocked_by & kWaitMask, kWaitMask);
}

TEST(BayindirController, LeaversFromATripleCountShrinkThenDissipation) {
  // All three leave in one step (p = 1); counted one after another the aggregate goes
  // 3 -> 2 (a shrink), 2 -> 1 (a dissipation), and the last leaver is no event.
  ControllerFixture f(bayindir(true, true, 1.0));
  f.add(10, 10, AgentState::Wait);
  f.add(13, 10, AgentState::Wait);
  f.add(16, 10, AgentState::Wait);
  f.decide();
  EXPECT_EQ(f.events.shrinks, 1u);
  EXPECT_EQ(f.events.dissipations, 1u);
}

TEST(BayindirController, NobodyLeavesWhenLeavingIsOff) {
  ControllerFixture f(bayindir(true, false, 1.0));
  const auto a = f.add(10, 10, AgentState::Wait);
  f.add(13, 10, AgentState::Wait);
  for (int k = 0; k < 50; ++k) f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.events.dissipations, 0u);
}

TEST(BayindirController, LeaveLastsTheTimeoutThenSearchesAgain) {
  ControllerFixture f(bayindir(true, true, 0.0));
  const auto a = f.add(10, 10, AgentState::Leave);
  f.swarm.leave_time_left[a] = 1.0;  // 10 steps of 0.1
  for (int k = 0; k < 9; ++k) {
    f.decide();
    ASSERT_EQ(f.swarm.state[a], AgentState::Leave) << "step " << k;
  }
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Go);
  EXPECT_NEAR(norm(f.swarm.heading[a]), 1.0, 1e-12);
}

TEST(BayindirController, AnIsolatedWaitingAgentResumesOrStaysAsConfigured) {
  ControllerFixture resume(bayindir(true, true, 0.0));
  const auto a = resume.add(10, 10, AgentState::Wait);
  resume.add(13, 10, AgentState::Leave);  // its partner, leaving
  resume.decide();
  EXPECT_EQ(resume.swarm.state[a], AgentState::Go);

  WorldSpec stay_spec = bayindir(true, true, 0.0);
  stay_spec.controller.isolated_wait = IsolatedWait::Stay;
  ControllerFixture stay(stay_spec);
  const auto b = stay.add(10, 10, AgentState::Wait);
  stay.add(13, 10, AgentState::Leave);
  stay.decide();
  EXPECT_EQ(stay.swarm.state[b], AgentState::Wait);
}

TEST(BayindirController, WithoutJoiningAWaitingAgentResumesWhenItsPartnerLeft) {
  ControllerFixture f(bayindir(false, true, 0.0));
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Leave);
  const auto c = f.add(10, 13, AgentState::Wait);  // an unrelated waiting agent nearby
  f.swarm.partner[a] = static_cast<std::int32_t>(b);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Go);
  EXPECT_EQ(f.swarm.state[c], AgentState::Go);  // c has no partner either
}

// isolated_wait: stay (issue 10): the pair dissolved when the partner left, so the agent
// that stays waits alone. A link kept to the old partner would join it to the partner's next
// pair: one aggregate of three under join: false, whose later leavers count as shrinks.
TEST(BayindirController, WithoutJoiningAStayingAgentDropsAPartnerWhoLeft) {
  WorldSpec spec = bayindir(false, true, 0.0);
  spec.controller.isolated_wait = IsolatedWait::Stay;
  ControllerFixture f(spec);
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Leave);  // a's partner, its timeout nearly over
  const auto c = f.add(13, 13, AgentState::Go);     // b's next partner
  f.swarm.partner[a] = static_cast<std::int32_t>(b);
  f.swarm.leave_time_left[b] = 0.1;
  f.decide();  // b searches again; c ignores the waiting a and the leaving b
  EXPECT_EQ(f.swarm.state[b], AgentState::Go);
  f.decide();  // b and c form a pair
  ASSERT_EQ(f.swarm.state[b], AgentState::Wait);
  ASSERT_EQ(f.swarm.partner[c], static_cast<std::int32_t>(b));
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.swarm.partner[a], kNoPartner);
  f.perceive();
  EXPECT_EQ(f.aggregates.count(), 1);
  EXPECT_EQ(f.aggregates.aggregate_of()[a], -1);
  EXPECT_EQ(f.aggregates.size_of_agent()[b], 2);
}

WorldSpec soysal() {
  WorldSpec spec;
  spec.controller.type = "soysal";
  spec.controller.approach_radius = 12.0;
  spec.controller.p0 = 0.0;
  return spec;
}

TEST(SoysalController, ASearcherApproachesTheNearestAgentWithinTheApproachRadius) {
  ControllerFixture f(soysal());
  const auto a = f.add(50, 50);
  f.add(50, 60);  // 10 away: within s_a = 12, beyond s = 4
  f.add(50, 39);  // 11 away
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Approach);
  EXPECT_NEAR(f.commands[a].velocity.x, 0.0, 1e-12);
  EXPECT_NEAR(f.commands[a].velocity.y, 1.0, 1e-12);
}

TEST(SoysalController, ApproachersIgnoreLeaversAndGiveUpWhenAlone) {
  ControllerFixture f(soysal());
  const auto a = f.add(50, 50, AgentState::Approach);
  f.add(50, 60, AgentState::Leave);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Go);
}

TEST(SoysalController, AnApproacherReachingSWaits) {
  ControllerFixture f(soysal());
  const auto a = f.add(50, 50, AgentState::Approach);
  f.add(50, 53.9, AgentState::Wait);
  f.add(50, 57.8, AgentState::Wait);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.events.growths, 1u);
}

TEST(LeaveProbability, FollowsTheLeaveLawAndSizeSource) {
  const LeaveRule constant{LeaveLaw::Constant, 0.02, LeaveSize::Aggregate};
  EXPECT_DOUBLE_EQ(leave_probability(constant, 5, 2), 0.02);
  const LeaveRule inverse{LeaveLaw::Inverse, 0.02, LeaveSize::Aggregate};
  EXPECT_DOUBLE_EQ(leave_probability(inverse, 4, 1), 0.005);
  const LeaveRule square{LeaveLaw::InverseSquare, 0.02, LeaveSize::Aggregate};
  EXPECT_DOUBLE_EQ(leave_probability(square, 2, 1), 0.005);
  const LeaveRule by_neighbours{LeaveLaw::Inverse, 0.02, LeaveSize::Neighbours};
  EXPECT_DOUBLE_EQ(leave_probability(by_neighbours, 10, 3), 0.005);  // 3 perceived + itself
}

TEST(CollisionController, PaperModePairsThenBothLeaveAtOnce) {
  WorldSpec spec;
  spec.controller.type = "collision";
  spec.controller.collision_mode = CollisionMode::Paper;
  spec.controller.leave_timeout = 1.0;
  ControllerFixture f(spec);
  const auto a = f.add(10, 10);
  const auto b = f.add(13, 10);
  f.spec.controller.join = false;  // the fixture links partners only, as the replicate does
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  EXPECT_EQ(f.events.creations, 1u);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Leave);
  EXPECT_EQ(f.swarm.state[b], AgentState::Leave);
  EXPECT_EQ(f.events.dissipations, 1u);
}

// docs/controllers.md, "Compaction". Waiting agents that go on waiting close up under the spring
// force of the waiting members of their aggregate they perceive.
constexpr SignalMask kLeaveMask = mask_of(static_cast<Signal>(AgentState::Leave));

TEST(Compaction, WaitingMembersPullEachOtherToTheSpacingAtMostAtV) {
  ControllerFixture f(bayindir(true, false, 0.0));
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13.5, 10, AgentState::Wait);
  f.add(10, 12.5, AgentState::Wait);
  f.decide();
  // a: 1.5 towards b, 0.5 towards c; |F| = 1.58 > 1, so at v = 1.
  const Vec2 force{1.5, 0.5};
  const Vec2 expected = force * (1.0 / norm(force));
  EXPECT_NEAR(f.commands[a].velocity.x, expected.x, 1e-12);
  EXPECT_NEAR(f.commands[a].velocity.y, expected.y, 1e-12);
  // b perceives only a (c is 4.30 away): 1.5, capped at v.
  EXPECT_NEAR(norm(f.commands[b].velocity), 1.0, 1e-12);
  EXPECT_EQ(f.swarm.state[a], AgentState::Wait);
  // A member closing up halts where a searcher that may join comes within s (both sides of
  // a meeting halt); one standing still has nothing to halt.
  constexpr SignalMask kApproachMask = mask_of(static_cast<Signal>(AgentState::Approach));
  EXPECT_EQ(f.commands[a].halt_on, kGoMask | kApproachMask);
  EXPECT_EQ(f.commands[a].blocked_by, kWaitMask | kLeaveMask | kGoMask | kApproachMask);
}

TEST(Compaction, BelowTheToleranceAWaitingAgentStandsExactlyStill) {
  WorldSpec spec = bayindir(true, false, 0.0);
  spec.controller.compaction.gain = 2.0;
  ControllerFixture f(spec);
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(12.04, 10, AgentState::Wait);  // |F| = 0.04 < 0.05
  const auto c = f.add(30, 10, AgentState::Wait);
  const auto d = f.add(32.3, 10, AgentState::Wait);  // |F| = 0.3: at gain 2, 0.6
  f.decide();
  EXPECT_EQ(f.commands[a].velocity, (Vec2{0.0, 0.0}));
  EXPECT_EQ(f.commands[b].velocity, (Vec2{0.0, 0.0}));
  EXPECT_NEAR(f.commands[c].velocity.x, 0.6, 1e-12);
  EXPECT_NEAR(f.commands[d].velocity.x, -0.6, 1e-12);
  EXPECT_EQ(f.commands[c].velocity.y, 0.0);
}

// A net force exactly at the tolerance moves the agent: only forces below it stand, however
// the controller shortcuts the standing ones. At distance 3, (3 - 2) / 3 * 3 is exactly 1.
TEST(Compaction, AForceExactlyAtTheToleranceMoves) {
  WorldSpec spec = bayindir(true, false, 0.0);
  spec.controller.compaction.tolerance = 1.0;
  spec.controller.compaction.gain = 0.5;
  ControllerFixture f(spec);
  const auto a = f.add(10, 10, AgentState::Wait);
  const auto b = f.add(13, 10, AgentState::Wait);
  f.decide();
  EXPECT_EQ(f.commands[a].velocity, (Vec2{0.5, 0.0}));
  EXPECT_EQ(f.commands[b].velocity, (Vec2{-0.5, 0.0}));
}

TEST(Compaction, OnlyWaitingMembersPullAndTooCloseOnesPush) {
  ControllerFixture f(bayindir(true, false, 0.0));
  f.spec.controller.compaction.spacing = 2.5;
  const auto a = f.add(10, 10, AgentState::Wait);
  f.add(12, 10, AgentState::Wait);   // 0.5 closer than the spacing: pushes a to -x
  f.add(10, 13, AgentState::Leave);  // not waiting: no force
  f.add(10, 5, AgentState::Go);      // searching, beyond s: no force
  f.decide();
  EXPECT_NEAR(f.commands[a].velocity.x, -0.5, 1e-12);
  EXPECT_NEAR(f.commands[a].velocity.y, 0.0, 1e-12);
}

// A searcher joining within s of a member that would close up: the member stands for the
// step, so that the newcomer, standing too, is still within s at the step's end (its force,
// from the states before, does not count the newcomer yet). A member with no newcomer within
// s closes up as usual.
TEST(Compaction, AMemberStandsWhileASearcherJoinsBesideIt) {
  ControllerFixture f(bayindir(true, false, 0.0));
  f.spec.controller.compaction.spacing = 2.5;
  const auto a = f.add(10, 10, AgentState::Wait);
  f.add(12, 10, AgentState::Wait);  // pushes a to -x
  const auto newcomer = f.add(10, 7, AgentState::Go);
  const auto c = f.add(40, 10, AgentState::Wait);
  f.add(42, 10, AgentState::Wait);  // pushes c to -x; nobody joins beside c
  f.decide();
  EXPECT_EQ(f.swarm.state[newcomer], AgentState::Wait);
  EXPECT_EQ(f.commands[a].velocity, (Vec2{0.0, 0.0}));
  EXPECT_NEAR(f.commands[c].velocity.x, -0.5, 1e-12);
}

TEST(Compaction, UnderJoinFalseOnlyThePartnerPulls) {
  ControllerFixture f(bayindir(false, false, 0.0));
  const auto a = f.add(10, 10);
  const auto b = f.add(13.5, 10);
  const auto c = f.add(40, 10);
  const auto d = f.add(40, 13.5);
  f.decide();  // two pairs form, standing this step
  EXPECT_EQ(f.swarm.partner[a], static_cast<std::int32_t>(b));
  EXPECT_EQ(f.commands[a].velocity, (Vec2{0.0, 0.0}));
  f.positions[c] = {12.0, 13.0};  // c now within s of a and b, but in the other pair
  f.positions[d] = {12.0, 16.5};
  f.decide();
  EXPECT_NEAR(f.commands[a].velocity.x, 1.0, 1e-12);
  EXPECT_NEAR(f.commands[a].velocity.y, 0.0, 1e-12);
  EXPECT_NEAR(f.commands[c].velocity.y, 1.0, 1e-12);
  EXPECT_NEAR(f.commands[c].velocity.x, 0.0, 1e-12);
}

TEST(Compaction, DisabledWaitingAgentsStandAndLeaversStayPassable) {
  WorldSpec spec = bayindir(true, false, 0.0);
  spec.controller.compaction.enabled = false;
  ControllerFixture f(spec);
  const auto a = f.add(10, 10, AgentState::Wait);
  f.add(13.5, 10, AgentState::Wait);
  f.decide();
  EXPECT_EQ(f.commands[a].velocity, (Vec2{0.0, 0.0}));
  EXPECT_EQ(f.commands[a].blocked_by, kWaitMask);
}

// A leaver with neighbours all around (the sum of the vectors to them under
// kEnclosedFraction of their lengths) draws its heading; one on the rim heads away.
TEST(Compaction, AnEnclosedLeaverDrawsARandomHeadingARimLeaverHeadsAway) {
  WorldSpec spec = bayindir(true, true, 1.0);  // everyone leaves at once
  ControllerFixture f(spec);
  const auto centre = f.add(50, 50, AgentState::Wait);
  for (int k = 0; k < 6; ++k) {
    const double angle = k * 3.141592653589793 / 3.0;
    f.add(50 + 2.0 * std::cos(angle), 50 + 2.0 * std::sin(angle), AgentState::Wait);
  }
  f.decide();
  ASSERT_EQ(f.swarm.state[centre], AgentState::Leave);
  const Vec2 drawn = random_heading(CounterRng(11), 0, centre, Draw::EnclosedLeave);
  EXPECT_EQ(f.swarm.heading[centre], drawn);
  EXPECT_NE(drawn, (Vec2{1.0, 0.0}));
  // Agent 1 (at +x) perceives the centre and its two neighbours, all to its -x side.
  EXPECT_NEAR(f.swarm.heading[1].x, 1.0, 1e-12);
  EXPECT_NEAR(f.swarm.heading[1].y, 0.0, 1e-12);
}

TEST(CollisionController, GhostModeMovesStraightAndTumbles) {
  WorldSpec spec;
  spec.controller.type = "collision";
  spec.controller.collision_mode = CollisionMode::Ghost;
  spec.controller.tumble = 1.0;
  ControllerFixture f(spec);
  const auto a = f.add(10, 10);
  f.add(12, 10);
  f.decide();
  EXPECT_EQ(f.swarm.state[a], AgentState::Go);
  EXPECT_EQ(f.commands[a].halt_on, 0u);
  EXPECT_NE(f.swarm.heading[a], (Vec2{1.0, 0.0}));  // tumble = 1 redraws every step
  EXPECT_NEAR(norm(f.commands[a].velocity), 1.0, 1e-12);
}

}  // namespace
}  // namespace swarmagg

namespace swarmagg {
namespace {

// A controller that keeps its last decision repeats it from memory while every agent waits,
// nothing changed and its inputs stay (the same lists, labels, partners), drawing only the
// leave decisions. Each of its decisions must be the one a fresh controller, which remembers
// nothing, makes from the same inputs: through steady stretches, leaves and what follows.
TEST(AggregationController, ASteadyAggregateDecidesAsAFreshControllerWould) {
  WorldSpec spec = soysal();
  spec.controller.p0 = 0.01;
  spec.arena = {100.0, 100.0, Topology::Torus};
  // Four waiting agents 2.5 apart: compaction pulls them in (their commands move them), and
  // nothing moves them here, so the lists stay as they are.
  const std::vector<Vec2> at{{50.0, 50.0}, {52.5, 50.0}, {50.0, 52.5}, {52.5, 52.5}};
  const auto n = static_cast<std::uint32_t>(at.size());
  const ArenaGeometry arena = spec.arena.geometry();
  std::vector<ClosePair> pairs;
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < n; ++j) {
      const Vec2 d = arena.displacement(at[i], at[j]);
      if (norm(d) <= spec.sensing_radius()) pairs.push_back({i, j, d, norm(d)});
    }
  }
  SwarmState swarm;
  for (std::uint32_t a = 0; a < n; ++a) swarm.add(AgentState::Wait);
  NeighbourLists lists;
  AggregateTracker aggregates;
  EventCounts remembered_events, fresh_events;
  std::vector<std::uint64_t> remembered_growths(n + 1, 0), fresh_growths(n + 1, 0);
  const std::vector<std::uint8_t> reflections(n, 0);
  std::vector<MotionCommand> remembered_commands(n), fresh_commands(n);
  const std::unique_ptr<Controller> remembering = make_controller(spec);
  const CounterRng rng(5);
  int leaves = 0, moving_commands = 0;
  for (std::int64_t step = 0; step < 600; ++step) {
    lists.assign_from_pairs(n, pairs);  // the same pairs: the same lists, generation kept
    aggregates.update(lists, swarm, spec.robots.detection_radius, AggregateLinks::Proximity);
    SwarmState fresh_swarm = swarm;
    const ControllerInput input{step, lists, reflections, aggregates.facts(), remembered_growths};
    const ControllerInput fresh_input{step, lists, reflections, aggregates.facts(), fresh_growths};
    remembering->decide(input, swarm, rng, remembered_commands, remembered_events);
    make_controller(spec)->decide(fresh_input, fresh_swarm, rng, fresh_commands, fresh_events);
    for (std::uint32_t a = 0; a < n; ++a) {
      ASSERT_TRUE(same_bits(remembered_commands[a].velocity, fresh_commands[a].velocity))
          << "agent " << a << " at step " << step;
      ASSERT_EQ(remembered_commands[a].blocked_by, fresh_commands[a].blocked_by);
      ASSERT_EQ(remembered_commands[a].halt_on, fresh_commands[a].halt_on);
      ASSERT_EQ(swarm.state[a], fresh_swarm.state[a]) << "agent " << a << " at step " << step;
      ASSERT_TRUE(same_bits(swarm.heading[a], fresh_swarm.heading[a]));
      ASSERT_EQ(swarm.partner[a], fresh_swarm.partner[a]);
      ASSERT_EQ(swarm.leave_time_left[a], fresh_swarm.leave_time_left[a]);
      leaves += swarm.state[a] == AgentState::Leave && fresh_swarm.state[a] == AgentState::Leave;
      moving_commands += remembered_commands[a].velocity.x != 0.0;
    }
    ASSERT_EQ(remembered_events.shrinks, fresh_events.shrinks);
    ASSERT_EQ(remembered_events.dissipations, fresh_events.dissipations);
    ASSERT_EQ(remembered_growths, fresh_growths);
  }
  EXPECT_GT(leaves, 0);           // the draws fired during the run
  EXPECT_GT(moving_commands, 0);  // and compaction commands were repeated
}

}  // namespace
}  // namespace swarmagg
