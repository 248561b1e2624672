#include "observers/aggregate_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "observers/aggregate_members.hpp"
#include "observers/observer_scene.hpp"

namespace swarmagg {
namespace {

using testing::Scene;

// r = 1, spacing 2r = 2: rim reach 2.4.
ShapeRules rules_for(const Scene& scene) {
  return {scene.arena, 1.0, RimRule::for_spacing(2.0)};
}

std::vector<AgentId> all_agents(const Scene& scene) {
  std::vector<AgentId> ids(scene.positions.size());
  std::iota(ids.begin(), ids.end(), 0u);
  return ids;
}

struct HexCase {
  int rings;
  int size;
  int rim;  // ring k of a hexagon holds 6k agents: the outermost ring is the rim
};

// By hand: the farthest members are the corners of the outer ring, rings x spacing from the
// centre, so R1 = 2 rings + r; every member touches its nearest fellow (spacing 2).
TEST(AggregateGeometry, HexagonalPacksHaveRimsOfSixTwelveEighteen) {
  for (const HexCase c : {HexCase{1, 7, 6}, HexCase{2, 19, 12}, HexCase{3, 37, 18}}) {
    Scene scene;
    scene.add_hexagon(50.0, 40.0, c.rings, 2.0);
    const std::vector<AgentId> members = all_agents(scene);
    ASSERT_EQ(static_cast<int>(members.size()), c.size);
    const AggregateShape shape = measure_aggregate(members, scene.positions, rules_for(scene));
    EXPECT_EQ(shape.size, c.size);
    EXPECT_EQ(shape.rim, c.rim) << c.size;
    EXPECT_NEAR(shape.outer_radius, 2.0 * c.rings + 1.0, 1e-9) << c.size;
    EXPECT_NEAR(shape.mean_member_spacing, 2.0, 1e-9) << c.size;
    EXPECT_NEAR(shape.centroid.x, 50.0, 1e-9);
    EXPECT_NEAR(shape.centroid.y, 40.0, 1e-9);
  }
}

// A pack of 91 (5 rings, from 64 members the grid counts) on the torus seam, a member nudged
// off the lattice: each member is on the rim by the grid exactly when by the pairwise scan, and
// the rim is the outer ring (30).
TEST(AggregateGeometry, TheRimCounterOfALargePackIsThePairwiseScans) {
  Scene scene;
  scene.add_hexagon(1.0, 99.0, 5, 2.0);
  scene.positions[40] = scene.arena.wrap(scene.positions[40] + Vec2{0.3, -0.2});
  const std::vector<AgentId> members = all_agents(scene);
  ASSERT_EQ(members.size(), 91u);
  const ShapeRules rules = rules_for(scene);
  const RimCounter rim(members, scene.positions, rules);
  int on_rim = 0;
  for (const AgentId i : members) {
    const bool scanned = rules.rim.on_rim(
        member_surroundings(i, members, scene.positions, rules).fellows_within_reach);
    EXPECT_EQ(rim.on_rim(i), scanned) << i;
    on_rim += rim.on_rim(i);
  }
  EXPECT_EQ(on_rim, measure_aggregate(members, scene.positions, rules).rim);
}

TEST(AggregateGeometry, ThePackOnTheTorusSeamHasTheSameShape) {
  Scene inside;
  inside.add_hexagon(50.0, 50.0, 2, 2.0);
  const AggregateShape whole =
      measure_aggregate(all_agents(inside), inside.positions, rules_for(inside));
  Scene corner;  // centred on the corner where all four sides meet: split four ways
  corner.add_hexagon(0.5, 99.5, 2, 2.0);
  // The last member first: the centroid is measured from a ring member across a seam.
  std::vector<AgentId> members = all_agents(corner);
  std::reverse(members.begin(), members.end());
  const AggregateShape split = measure_aggregate(members, corner.positions, rules_for(corner));
  EXPECT_EQ(split.rim, whole.rim);
  EXPECT_NEAR(split.outer_radius, whole.outer_radius, 1e-9);
  EXPECT_NEAR(split.mean_member_spacing, whole.mean_member_spacing, 1e-9);
  EXPECT_NEAR(split.centroid.x, 0.5, 1e-9);
  EXPECT_NEAR(split.centroid.y, 99.5, 1e-9);
}

// Large aggregates find fellows in a grid of their members, small ones compare every pair:
// both give the definition's values bit for bit. A pack of 127 (rings 6) with jittered
// members, across the torus corner and inside a walled arena, plus a straggler 3.5 from its
// nearest fellow (beyond the rim reach of 2.4, so beyond the grid's guarantee).
TEST(AggregateGeometry, LargeAggregatesMeasureAsEveryPairWould) {
  for (const Topology topology : {Topology::Torus, Topology::Walls}) {
    Scene scene;
    scene.arena = ArenaGeometry(100.0, 100.0, topology);
    const double x = topology == Topology::Torus ? 1.0 : 50.0;
    scene.add_hexagon(x, x, 6, 2.1);
    for (std::size_t i = 0; i < scene.positions.size(); ++i) {
      const double jitter = 0.05 * std::sin(7.0 * static_cast<double>(i));
      scene.positions[i] = scene.arena.wrap(scene.positions[i] + Vec2{jitter, -jitter});
    }
    scene.positions.push_back(scene.arena.wrap(scene.positions.front() + Vec2{-3.5, 0.0}));
    const std::vector<AgentId> members = all_agents(scene);
    ASSERT_GE(members.size(), 64u);
    const ShapeRules rules = rules_for(scene);
    double nearest_sum = 0.0;
    int rim = 0;
    for (const AgentId i : members) {
      const MemberSurroundings around = member_surroundings(i, members, scene.positions, rules);
      nearest_sum += around.nearest_fellow;
      rim += rules.rim.on_rim(around.fellows_within_reach);
    }
    const AggregateShape shape = measure_aggregate(members, scene.positions, rules);
    EXPECT_EQ(shape.rim, rim);
    EXPECT_EQ(shape.mean_member_spacing, nearest_sum / static_cast<double>(members.size()));
    EXPECT_GT(rim, 30);  // the outer ring and the straggler, not every member
  }
}

// A rim is relative to the spacing: the same pack at spacing 3 measured with the 2r rule
// has no member with a fellow within 2.4, so all are rim.
TEST(AggregateGeometry, RimFollowsTheSpacingParameter) {
  Scene scene;
  scene.add_hexagon(50.0, 50.0, 2, 3.0);
  const std::vector<AgentId> members = all_agents(scene);
  EXPECT_EQ(measure_aggregate(members, scene.positions, rules_for(scene)).rim, 19);
  const ShapeRules at_three{scene.arena, 1.0, RimRule::for_spacing(3.0)};
  EXPECT_EQ(measure_aggregate(members, scene.positions, at_three).rim, 12);
  EXPECT_NEAR(measure_aggregate(members, scene.positions, at_three).mean_member_spacing, 3.0, 1e-9);
}

// A chain 0 - 1 - 2 at 2, 3: nearest fellows 2, 2, 3.
TEST(AggregateGeometry, MemberSpacingIsTheMeanNearestFellowDistance) {
  Scene scene;
  scene.add(10.0, 10.0);
  scene.add(12.0, 10.0);
  scene.add(15.0, 10.0);
  const AggregateShape shape =
      measure_aggregate(all_agents(scene), scene.positions, rules_for(scene));
  EXPECT_NEAR(shape.mean_member_spacing, 7.0 / 3.0, 1e-12);
  EXPECT_NEAR(shape.centroid.x, 37.0 / 3.0, 1e-12);
  EXPECT_NEAR(shape.outer_radius, 15.0 - 37.0 / 3.0 + 1.0, 1e-12);
  EXPECT_EQ(shape.rim, 3);
}

TEST(AggregateMembers, GroupsEachAggregatesMembersInIndexOrder) {
  Scene scene;
  scene.add(10.0, 10.0);                     // 0: aggregate 0
  scene.add(60.0, 60.0);                     // 1: aggregate 1
  scene.add(13.0, 10.0);                     // 2: aggregate 0
  scene.add(30.0, 30.0);                     // 3: alone
  scene.add(63.0, 60.0);                     // 4: aggregate 1
  scene.add(16.0, 10.0);                     // 5: aggregate 0
  scene.add(19.0, 10.0, AgentState::Leave);  // 6: not waiting
  scene.update();
  AggregateMembers members;
  members.build(scene.tracker);
  ASSERT_EQ(members.count(), 2);
  EXPECT_EQ(std::vector<AgentId>(members.of(0).begin(), members.of(0).end()),
            (std::vector<AgentId>{0, 2, 5}));
  EXPECT_EQ(std::vector<AgentId>(members.of(1).begin(), members.of(1).end()),
            (std::vector<AgentId>{1, 4}));
  const std::vector<AggregateShape> shapes =
      measure_aggregates(members, scene.positions, rules_for(scene));
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(shapes[0].size, 3);
  EXPECT_EQ(shapes[1].size, 2);
}

}  // namespace
}  // namespace swarmagg
