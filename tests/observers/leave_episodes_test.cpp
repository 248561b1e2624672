#include "observers/leave_episodes.hpp"

#include <gtest/gtest.h>

#include "observers/observer_scene.hpp"

namespace swarmagg {
namespace {

using testing::Scene;

// One step as a replicate runs it: perception and aggregates of the states the decision
// starts from, then the decided states, then the observation.
// Decisions within which a return counts; the tests of the LEAVE phase alone count none, so
// that an attempt is decided when its timeout ends.
constexpr std::int64_t kWindow = 30;

struct Stepper {
  explicit Stepper(std::int64_t window = 0, double escape_radius = Scene::kDetectionRadius)
      : episodes{64, EpisodeRules{escape_radius, Scene::kDetectionRadius, window},
                 ShapeRules{scene.arena, 1.0, RimRule::for_spacing(2.0)}} {}
  Scene scene;
  LeaveEpisodes episodes;

  template <typename Decide>
  void step(Decide decide) {
    scene.update();
    decide(scene.swarm.state);
    episodes.observe_decision(scene.tracker, scene.neighbours, scene.positions, scene.swarm.state);
  }
};

// A 7-hexagon at 2r: the centre (0) is inside, the ring (1..6) is rim (docs/models.md).
TEST(LeaveEpisodes, SplitsAttemptsByRimAndInside) {
  Stepper s;
  const AgentId centre = s.scene.add_hexagon(50.0, 50.0, 1, 2.0);
  const AgentId ring = centre + 1;
  s.step([&](auto& state) {
    state[centre] = AgentState::Leave;
    state[ring] = AgentState::Leave;
  });
  const LeaveTally& t = s.episodes.tally();
  EXPECT_EQ(t.attempts.inside, 1);
  EXPECT_EQ(t.attempts.rim, 1);
  EXPECT_EQ(t.attempts.total(), 2);
  EXPECT_EQ(t.attempts_by_size[7], 2);
  EXPECT_EQ(t.aggregate_steps_by_size[7], 1);
  EXPECT_EQ(s.episodes.open_attempts(), 2u);
  EXPECT_EQ(t.escapes.total(), 0);
}

// The centre stays surrounded by its waiting fellows: no escape. The ring agent walked
// away and ends beside a waiting agent of another aggregate: still an escape, since only
// the members of the aggregate it left count.
TEST(LeaveEpisodes, AnEscapeIsJudgedOnTheAggregateItLeft) {
  Stepper s;
  const AgentId centre = s.scene.add_hexagon(50.0, 50.0, 1, 2.0);
  const AgentId ring = centre + 1;  // at (48, 50)
  const AgentId other_a = s.scene.add(70.0, 50.0);
  s.scene.add(72.0, 50.0);
  s.step([&](auto& state) {
    state[centre] = AgentState::Leave;
    state[ring] = AgentState::Leave;
  });
  s.scene.positions[ring] = {67.0, 50.0};  // 3 from the other pair, 15 from its own
  s.step([](auto&) {});                    // still leaving
  EXPECT_EQ(s.episodes.tally().escapes.total(), 0);
  s.step([&](auto& state) {  // timeouts: LEAVE -> GO
    state[centre] = AgentState::Go;
    state[ring] = AgentState::Go;
  });
  const LeaveTally& t = s.episodes.tally();
  EXPECT_EQ(t.escapes.rim, 1);
  EXPECT_EQ(t.escapes.inside, 0);
  EXPECT_EQ(t.escapes_by_size[7], 1);
  EXPECT_EQ(t.aggregate_steps_by_size[7], 1);  // then 5 (the ring without agent 1) twice
  EXPECT_EQ(t.aggregate_steps_by_size[5], 2);
  EXPECT_EQ(t.aggregate_steps_by_size[2], 3);  // the other pair, every step
  EXPECT_EQ(s.episodes.open_attempts(), 0u);
  EXPECT_EQ(s.scene.swarm.state[other_a], AgentState::Wait);
}

// Former members that are no longer waiting do not hold the leaver: a pair whose partner
// left first dissolves, so the second leaver got out even though it stands beside it.
TEST(LeaveEpisodes, FormerMembersThatStoppedWaitingDoNotCount) {
  Stepper s;
  const AgentId a = s.scene.add(20.0, 20.0);
  const AgentId b = s.scene.add(22.0, 20.0);
  s.step([&](auto& state) { state[a] = AgentState::Leave; });
  s.step([&](auto& state) { state[b] = AgentState::Go; });  // alone: resumes
  s.step([&](auto& state) { state[a] = AgentState::Go; });  // timeout beside b (GO)
  EXPECT_EQ(s.episodes.tally().attempts.total(), 1);
  EXPECT_EQ(s.episodes.tally().escapes.rim, 1);
}

// Nor one that stopped waiting and waits again: the partner searched again when the pair fell
// apart, then stopped beside a third agent, next to the leaver when its LEAVE ends. It is
// waiting, but not still: the leaver escaped (counted held, a world's pairs escaped 49 times in
// 60 attempts though almost none could be held). One that kept waiting holds it (the first test).
TEST(LeaveEpisodes, AFormerMemberThatWaitsAgainDoesNotHold) {
  Stepper s;
  const AgentId a = s.scene.add(20.0, 20.0);
  const AgentId b = s.scene.add(22.0, 20.0);
  const AgentId c = s.scene.add(24.0, 20.0, AgentState::Go);  // searching, not a member
  s.step([&](auto& state) { state[a] = AgentState::Leave; });
  s.step([&](auto& state) { state[b] = AgentState::Go; });               // alone: resumes
  s.step([&](auto& state) { state[b] = state[c] = AgentState::Wait; });  // pairs with c
  s.step([&](auto& state) { state[a] = AgentState::Go; });  // timeout, 2 from waiting b
  EXPECT_EQ(s.scene.swarm.state[b], AgentState::Wait);
  EXPECT_EQ(s.episodes.tally().attempts.total(), 1);
  EXPECT_EQ(s.episodes.tally().escapes.rim, 1);
}

// A lone waiting agent (isolated_wait: stay) has no aggregate to leave.
TEST(LeaveEpisodes, ALoneWaitingAgentMakesNoAttempt) {
  Stepper s;
  const AgentId lone = s.scene.add(20.0, 20.0);
  s.step([&](auto& state) { state[lone] = AgentState::Leave; });
  EXPECT_EQ(s.episodes.tally().attempts.total(), 0);
  EXPECT_EQ(s.episodes.open_attempts(), 0u);
}

// Many overlapping episodes: the remembered members are compacted as attempts end, and each
// attempt still judges against its own aggregate. Two 19-packs; each step one ring-2 agent
// of each leaves (rim), and the attempts of two steps before end where they started, within
// s of the inner seven, who never leave: no escape, except one leaver of the first pack
// moved beside the second pack's centre, whose members it never belonged to.
TEST(LeaveEpisodes, ManyOverlappingAttemptsKeepTheirOwnMembers) {
  Stepper s;
  const AgentId first = s.scene.add_hexagon(20.0, 20.0, 2, 2.0);
  const AgentId second = s.scene.add_hexagon(70.0, 70.0, 2, 2.0);
  const AgentId moved = first + 7 + 3;
  for (int k = 0; k < 12; ++k) {
    const AgentId a = first + 7 + static_cast<AgentId>(k);
    const AgentId b = second + 7 + static_cast<AgentId>(k);
    if (k == 5) s.scene.positions[moved] = {70.0, 73.0};  // 3 from the second centre
    s.step([&](auto& state) {
      state[a] = state[b] = AgentState::Leave;
      if (k >= 2) state[a - 2] = state[b - 2] = AgentState::Go;
    });
  }
  const LeaveTally& t = s.episodes.tally();
  EXPECT_EQ(t.attempts.rim, 24);
  EXPECT_EQ(t.attempts.inside, 0);
  EXPECT_EQ(s.episodes.open_attempts(), 4u);
  EXPECT_EQ(t.escapes.rim, 1);
  EXPECT_EQ(t.escapes.inside, 0);
  // Step k starts from packs of 19 - k waiting members.
  for (int m = 8; m <= 19; ++m) EXPECT_EQ(t.attempts_by_size[m], 2) << m;
  EXPECT_EQ(t.escapes_by_size[19 - 3], 1);
}

// Returns: a triangle at (20, 20); agent `leaver` leaves, walks 6 away, and its timeout ends
// there (outside s: an escape). What it does next decides whether it returned.
struct ReturnScene {
  Stepper s{kWindow};
  AgentId first = 0, leaver = 0;
  ReturnScene() {
    first = s.scene.add(20.0, 20.0);
    s.scene.add(22.0, 20.0);
    leaver = s.scene.add(21.0, 21.7);
    s.step([&](auto& state) { state[leaver] = AgentState::Leave; });  // decision 1: attempt
    s.scene.positions[leaver] = {21.0, 28.0};
    s.step([](auto&) {});                                          // 2: still leaving
    s.step([&](auto& state) { state[leaver] = AgentState::Go; });  // 3: timeout, escape
  }
  // Decisions in GO, then it waits at `where` (seen in an aggregate one decision later).
  void wait_at(Vec2 where, int decisions_in_go) {
    for (int k = 0; k < decisions_in_go; ++k) s.step([](auto&) {});
    s.scene.positions[leaver] = where;
    s.step([&](auto& state) { state[leaver] = AgentState::Wait; });
    s.step([](auto&) {});
  }
  // The pair the leaver left falls apart (one decision): its members search again, the second
  // walking off; `first_searches` false keeps the first waiting alone.
  void pair_falls_apart(bool first_searches = true) {
    const AgentId second = first + 1;
    s.step([&](auto& state) {
      state[second] = AgentState::Go;
      if (first_searches) state[first] = AgentState::Go;
    });
    s.scene.positions[second] = {60.0, 60.0};
  }
  // Steps on until the attempt's return window (kWindow decisions from decision 1) closed.
  void close_window() {
    for (int k = 0; k <= kWindow; ++k) s.step([](auto&) {});
  }
};

TEST(LeaveEpisodes, ALeaverThatComesBackReturns) {
  ReturnScene r;
  EXPECT_EQ(r.s.episodes.tally().escapes_by_size[3], 1);
  EXPECT_EQ(r.s.episodes.open_attempts(), 1u);  // on its excursion
  r.wait_at({21.0, 21.7}, 4);                   // waits again at decision 8
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.returns_into_size[2], 1);  // the pair it left behind: no new join
  // The return fraction takes it once its window closed: a run ending earlier leaves it out,
  // as it leaves out the attempts still away then.
  EXPECT_EQ(t.return_attempts_by_size[3], 0);
  r.close_window();
  EXPECT_EQ(t.return_attempts_by_size[3], 1);
  EXPECT_EQ(t.returns_by_size[3], 1);
  EXPECT_EQ(t.return_steps_by_size[3], 8 - 1);  // from decision 1 to decision 8
  // Away from decision 1 to 8 it saw the pair (size 2) at decisions 2..8 and its triangle
  // (size 3) at none of them: the triangle was counted at decision 1, before it left.
  EXPECT_EQ(t.returning_aggregate_steps_by_size[2], 7);
  EXPECT_EQ(t.returning_aggregate_steps_by_size[3], 0);
  EXPECT_EQ(r.s.episodes.open_attempts(), 0u);
}

TEST(LeaveEpisodes, JoiningAnotherAggregateIsNoReturn) {
  ReturnScene r;
  r.s.scene.add(60.0, 60.0);
  r.s.scene.add(62.0, 60.0);
  r.wait_at({61.0, 61.7}, 4);
  r.close_window();
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.return_attempts_by_size[3], 1);
  EXPECT_EQ(t.returns_by_size[3], 0);
  EXPECT_EQ(t.returns_into_size[2], 0);
  EXPECT_EQ(t.returning_aggregate_steps_by_size[2], 0);
  EXPECT_EQ(r.s.episodes.open_attempts(), 0u);  // decided: it waited elsewhere
}

// An attempt still away when the run ends could yet come back: it counts as an attempt, not
// in the return fraction (which took it as a failure to return, 15 % of a 200-tu run's).
TEST(LeaveEpisodes, AnAttemptTheRunCutsShortIsLeftOutOfTheReturnFraction) {
  ReturnScene r;
  for (int k = 0; k < 10; ++k) r.s.step([](auto&) {});
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.attempts_by_size[3], 1);
  EXPECT_EQ(t.return_attempts_by_size[3], 0);
  EXPECT_EQ(r.s.episodes.open_attempts(), 1u);
  r.close_window();  // never came back: now a failure to return
  EXPECT_EQ(t.return_attempts_by_size[3], 1);
  EXPECT_EQ(t.returns_by_size[3], 0);
}

// The pair it left falls apart (its two members search again) and the leaver then pairs with
// one of them: a new aggregate, a creation, not a return (the models count it as a creation;
// as a return too, the measured model kept the pair and created it again).
TEST(LeaveEpisodes, PairingAgainWithAFormerMemberIsNoReturn) {
  ReturnScene r;
  r.pair_falls_apart();
  r.s.scene.positions[r.leaver] = {21.0, 21.7};
  r.s.step([&](auto& state) { state[r.first] = state[r.leaver] = AgentState::Wait; });
  r.s.step([](auto&) {});  // seen in the new pair
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.returns_by_size[3], 0);
  EXPECT_EQ(t.returns_into_size[1], 0);
  EXPECT_EQ(r.s.episodes.open_attempts(), 0u);  // decided: it waits in an aggregate
}

// Under isolated_wait: stay the member left alone keeps waiting: coming back to it restores
// the pair, a return, filed as the controllers file that join: under size 0, no aggregate.
TEST(LeaveEpisodes, ComingBackToAMemberThatWaitedAloneReturns) {
  ReturnScene r;
  r.pair_falls_apart(false);  // the first waits alone
  r.wait_at({21.0, 21.7}, 1);
  r.close_window();
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.returns_by_size[3], 1);
  EXPECT_EQ(t.returns_into_size[0], 1);
}

// Two agents join one pair in the same decision, the leaver among them: its return is filed
// under 2, as both growths are, not under the 3 the tracker sees after the other's join (found
// by the rates audit: join_new was up to 11 % too high at small sizes, 11-40 % too low at large).
TEST(LeaveEpisodes, AReturnIsFiledUnderTheSizeItsJoinWasCountedAt) {
  ReturnScene r;
  const AgentId other = r.s.scene.add(19.0, 18.3, AgentState::Go);
  r.s.scene.positions[r.leaver] = {21.0, 21.7};
  r.s.step([&](auto& state) { state[other] = state[r.leaver] = AgentState::Wait; });
  r.s.step([](auto&) {});
  r.close_window();
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.returns_by_size[3], 1);
  EXPECT_EQ(t.returns_into_size[2], 1);
  EXPECT_EQ(t.returns_into_size[3], 0);
}

// Its pair falls apart; the former member searches, then waits again at the same moment as
// the leaver and a stranger beside it: a new aggregate of three (found by review: an aggregate
// of two or more before the leaver came was taken for one that lasted).
TEST(LeaveEpisodes, ANewAggregateFormedWithAFormerMemberIsNoReturn) {
  ReturnScene r;
  const AgentId stranger = r.s.scene.add(40.0, 40.0, AgentState::Go);
  r.pair_falls_apart();
  r.s.scene.positions[stranger] = {22.0, 20.0};
  r.s.scene.positions[r.leaver] = {21.0, 21.7};
  r.s.step(
      [&](auto& state) { state[r.first] = state[stranger] = state[r.leaver] = AgentState::Wait; });
  r.s.step([](auto&) {});
  r.close_window();
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.return_attempts_by_size[3], 1);
  EXPECT_EQ(t.returns_by_size[3], 0);
}

// The former member searched again and paired with a stranger; the leaver joins that new pair.
TEST(LeaveEpisodes, JoiningAFormerMembersNewPairIsNoReturn) {
  ReturnScene r;
  const AgentId stranger = r.s.scene.add(22.0, 20.0, AgentState::Go);
  r.pair_falls_apart();
  r.s.step([&](auto& state) { state[r.first] = state[stranger] = AgentState::Wait; });
  r.wait_at({21.0, 21.7}, 1);
  r.close_window();
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.returns_by_size[3], 0);
  EXPECT_EQ(t.returns_into_size[2], 0);
}

TEST(LeaveEpisodes, ComingBackAfterTheWindowIsNoReturn) {
  ReturnScene r;
  r.wait_at({21.0, 21.7}, static_cast<int>(kWindow));  // waits again at decision 34 > 1 + 30
  const LeaveTally& t = r.s.episodes.tally();
  EXPECT_EQ(t.return_attempts_by_size[3], 1);
  EXPECT_EQ(t.returns_by_size[3], 0);
  EXPECT_EQ(t.return_steps_by_size[3], 0);
  EXPECT_EQ(r.s.episodes.open_attempts(), 0u);  // given up when the window passed
}

// The escape radius decides whether a leaver 4.5 from its nearest former member at its
// timeout got out: yes within s = 4, no within an approach radius of 6 (Scene sees 6 far).
TEST(LeaveEpisodes, TheEscapeRadiusDecidesWhetherALeaverIsHeld) {
  for (const double radius : {Scene::kDetectionRadius, 6.0}) {
    Stepper s{kWindow, radius};
    s.scene.add(20.0, 20.0);
    s.scene.add(22.0, 20.0);
    const AgentId leaver = s.scene.add(21.0, 21.7);
    s.step([&](auto& state) { state[leaver] = AgentState::Leave; });
    s.scene.positions[leaver] = {21.0, 24.5};  // 4.5 from (20, 20) and (22, 20)
    s.step([&](auto& state) { state[leaver] = AgentState::Go; });
    EXPECT_EQ(s.episodes.tally().escapes_by_size[3], radius < 4.5 ? 1 : 0) << radius;
  }
}

}  // namespace
}  // namespace swarmagg

namespace swarmagg {
namespace {

// Two leavers of one aggregate in each of six decisions share its member list (one FormerSet
// with two users); sets die as their attempts end and are compacted away. The tallies are those
// of one list per attempt: 12 rim attempts, by size 9 .. 19, one escape (the pair whose
// fellow members went GO and moved off).
TEST(LeaveEpisodes, LeaversOfOneAggregateInOneDecisionShareItsMembers) {
  Stepper s;
  const AgentId first = s.scene.add_hexagon(20.0, 20.0, 2, 2.0);
  s.scene.add_hexagon(70.0, 70.0, 2, 2.0);
  const AgentId moved = first + 7 + 5;
  for (int k = 0; k < 6; ++k) {
    const AgentId a = first + 7 + static_cast<AgentId>(2 * k);
    if (k == 3) s.scene.positions[moved] = {70.0, 73.0};
    s.step([&](auto& state) {
      state[a] = state[a + 1] = AgentState::Leave;
      if (k >= 2) state[a - 4] = state[a - 3] = AgentState::Go;
    });
  }
  const LeaveTally& t = s.episodes.tally();
  EXPECT_EQ(t.attempts.rim, 12);
  EXPECT_EQ(t.escapes.rim, 1);
  EXPECT_EQ(s.episodes.open_attempts(), 4u);
  for (int m = 9; m <= 19; m += 2) EXPECT_EQ(t.attempts_by_size[m], 2) << m;
  EXPECT_EQ(t.escapes_by_size[19 - 4], 1);
}

}  // namespace
}  // namespace swarmagg
