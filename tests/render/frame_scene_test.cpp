#include "render/frame_scene.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "render_testing.hpp"

namespace swarmagg {
namespace {

using testing::Swarm;

FrameLayout layout_for(const WorldSpec& spec, int size = 400) {
  return make_frame_layout(size, size, spec.arena);
}

TEST(FrameScene, DrawsOneCopyOfAnAgentAwayFromTheSeam) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(20, 20, AgentState::Go);
  FrameSceneBuilder builder;
  const FrameScene& scene = builder.build(swarm.snapshot(), layout_for(spec));
  EXPECT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.rings.size(), 1u);
  EXPECT_TRUE(scene.tints.empty());
  EXPECT_TRUE(scene.links.empty());
  EXPECT_TRUE(scene.walls.empty());
  EXPECT_EQ(scene.bodies[0].fill, palette::kGo);
}

TEST(FrameScene, CopiesShapesThatCrossTheSeam) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(3.0, 20, AgentState::Go);     // its detection circle (s = 4) crosses x = 0
  swarm.add(20, 38.0, AgentState::Go);    // crosses y = 40
  swarm.add(1.0, 1.0, AgentState::Go);    // a corner: four copies
  swarm.add(-2.0, 45.0, AgentState::Go);  // outside the arena: wrapped to (38, 5) first
  FrameSceneBuilder builder;
  const FrameLayout layout = layout_for(spec);
  const FrameScene& scene = builder.build(swarm.snapshot(), layout);
  EXPECT_EQ(scene.bodies.size(), 2u + 2u + 4u + 2u);
  EXPECT_EQ(scene.rings.size(), scene.bodies.size());
  // The copy of the first agent sits one arena width to the right.
  const Vec2 copy = layout.to_pixel({43.0, 20});
  EXPECT_NEAR(scene.bodies[1].x, copy.x, 1e-3);
  EXPECT_NEAR(scene.bodies[1].y, copy.y, 1e-3);
  const Vec2 wrapped = layout.to_pixel({38.0, 5.0});
  EXPECT_NEAR(scene.bodies[8].x, wrapped.x, 1e-3);
  EXPECT_NEAR(scene.bodies[8].y, wrapped.y, 1e-3);
}

TEST(FrameScene, WallsNeverCopyAndDrawAFourSidedBorder) {
  const WorldSpec spec = testing::tiny_world(40, 40, Topology::Walls);
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(1.0, 1.0, AgentState::Go);
  FrameSceneBuilder builder;
  const FrameScene& scene = builder.build(swarm.snapshot(), layout_for(spec));
  EXPECT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.walls.size(), 4u);
}

TEST(FrameScene, SizesFollowTheWorld) {
  WorldSpec spec = testing::tiny_world();
  spec.robots.radius = 1.5;
  spec.robots.detection_radius = 6.0;
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(20, 20, AgentState::Wait, 0);
  swarm.add(24, 20, AgentState::Wait, 0);
  FrameSceneBuilder builder;
  const FrameLayout layout = layout_for(spec);
  const FrameScene& scene = builder.build(swarm.snapshot(), layout);
  EXPECT_NEAR(scene.bodies[0].radius, 1.5 * layout.scale, 1e-3);
  EXPECT_NEAR(scene.rings[0].radius - scene.rings[0].line / 2, 6.0 * layout.scale, 1e-3);
  ASSERT_EQ(scene.tints.size(), 2u);
  EXPECT_NEAR(scene.tints[0].radius, 3.0 * layout.scale, 1e-3);
  EXPECT_EQ(scene.tints[0].fill, scene.tints[1].fill);  // one aggregate, one tint
  EXPECT_EQ(scene.links.size(), 1u);
}

TEST(FrameScene, TinyBodiesStayVisible) {
  WorldSpec spec = testing::tiny_world(2000, 2000);
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(1000, 1000);
  FrameSceneBuilder builder;
  const FrameScene& scene = builder.build(swarm.snapshot(), layout_for(spec, 200));
  EXPECT_EQ(scene.bodies[0].radius, kMinBodyPixels);
}

TEST(FrameScene, AggregateTintFollowsTheLowestMemberNotTheIndex) {
  const WorldSpec spec = testing::tiny_world();
  Swarm a;
  a.spec = &spec;
  a.add(10, 10, AgentState::Wait, 0);
  a.add(12, 10, AgentState::Wait, 0);
  a.add(30, 30, AgentState::Wait, 1);
  a.add(32, 30, AgentState::Wait, 1);
  Swarm b = a;  // the same aggregates, numbered the other way round
  b.aggregate = {1, 1, 0, 0};
  FrameSceneBuilder builder;
  const FrameLayout layout = layout_for(spec);
  const auto tints_a = builder.build(a.snapshot(), layout).tints;
  const auto tints_b = builder.build(b.snapshot(), layout).tints;
  ASSERT_EQ(tints_a.size(), 4u);
  ASSERT_EQ(tints_b.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(tints_a[i].fill, tints_b[i].fill);
  EXPECT_EQ(tints_a[0].fill, palette::aggregate_tint(0));
  EXPECT_EQ(tints_a[2].fill, palette::aggregate_tint(2));
}

// Links are exactly the same-aggregate pairs within s (minimum image), whether found by
// brute force (few members) or by the grid (many).
void expect_links_match_brute_force(Topology topology) {
  WorldSpec spec = testing::tiny_world(120, 90, topology);
  Swarm swarm = testing::random_swarm(spec, 600, 0.6, 11);
  // Aggregates straddling both seams.
  const int base = swarm.noa;
  for (int m = 0; m < 6; ++m) swarm.add(119.0 + 1.5 * m, 45, AgentState::Wait, base);
  for (int m = 0; m < 6; ++m) swarm.add(60, 88.5 + 1.5 * m, AgentState::Wait, base + 1);
  // Two different aggregates within s of each other must stay unlinked.
  swarm.add(30, 30, AgentState::Wait, base + 2);
  swarm.add(32, 30, AgentState::Wait, base + 3);
  const bool torus = topology == Topology::Torus;

  const FrameLayout layout = layout_for(spec);
  std::size_t expected_pairs = 0;
  for (std::size_t i = 0; i < swarm.positions.size(); ++i) {
    for (std::size_t j = i + 1; j < swarm.positions.size(); ++j) {
      if (swarm.aggregate[i] < 0 || swarm.aggregate[i] != swarm.aggregate[j]) continue;
      Vec2 d = swarm.positions[j] - swarm.positions[i];
      if (torus) {
        d.x -= spec.arena.width * std::round(d.x / spec.arena.width);
        d.y -= spec.arena.height * std::round(d.y / spec.arena.height);
      }
      if (norm(d) <= spec.robots.detection_radius) ++expected_pairs;
    }
  }
  FrameSceneBuilder builder;
  const FrameScene& scene = builder.build(swarm.snapshot(), layout);
  // Each pair is drawn once per copy of its first agent: at least once, and every segment
  // is at most s long.
  EXPECT_GE(scene.links.size(), expected_pairs);
  EXPECT_GT(expected_pairs, 200u);
  for (const auto& link : scene.links) {
    const double length = std::hypot(link.x1 - link.x0, link.y1 - link.y0) / layout.scale;
    EXPECT_LE(length, spec.robots.detection_radius * (1 + 1e-5));
  }
  // Without seam copies (walls) there is exactly one segment per pair.
  if (!torus) {
    EXPECT_EQ(scene.links.size(), expected_pairs);
  }
}

TEST(FrameScene, LinksMatchBruteForceOnATorus) {
  expect_links_match_brute_force(Topology::Torus);
}
TEST(FrameScene, LinksMatchBruteForceWithWalls) {
  expect_links_match_brute_force(Topology::Walls);
}

TEST(FrameScene, LinksOnATorusAreDrawnOncePerCopyOfTheirFirstAgent) {
  const WorldSpec spec = testing::tiny_world(120, 90);
  Swarm swarm;
  swarm.spec = &spec;
  // 55 members 2 apart in a row that crosses the x seam (enough members for the grid).
  for (int m = 0; m < 55; ++m)
    swarm.add(std::fmod(100.0 + 2.0 * m, 120.0), 45, AgentState::Wait, 0);
  FrameSceneBuilder builder;
  const FrameLayout layout = layout_for(spec);
  const FrameScene& scene = builder.build(swarm.snapshot(), layout);
  // A shape is copied when the agent's reach (detection circle + line + 1 pixel; 1.5 pixels
  // at this size) crosses the seam.
  const double reach = spec.robots.detection_radius + 1.5 / layout.scale;
  std::size_t pairs = 0;
  std::size_t segments = 0;
  for (int i = 0; i < 55; ++i) {
    for (int j = i + 1; j < 55; ++j) {
      double d = swarm.positions[j].x - swarm.positions[i].x;
      d -= 120.0 * std::round(d / 120.0);
      if (std::abs(d) > 4.0) continue;
      ++pairs;
      const double x = swarm.positions[i].x;
      segments += 1 + (x < reach ? 1 : 0) + (x > 120.0 - reach ? 1 : 0);
    }
  }
  EXPECT_EQ(pairs, 54u + 53u);  // neighbours 2 apart and second neighbours 4 apart
  EXPECT_EQ(scene.links.size(), segments);
}

TEST(FrameScene, RejectsInconsistentSnapshots) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(1, 1);
  SwarmSnapshot snapshot = swarm.snapshot();
  snapshot.states = {};
  FrameSceneBuilder builder;
  EXPECT_THROW(builder.build(snapshot, layout_for(spec)), std::invalid_argument);
}

}  // namespace
}  // namespace swarmagg
