// The view options of the scene (scene_options.hpp): colour modes, radius overlays, torus
// ghosts, selection, extra links, zoom, and picking an agent under a pixel, all without GL.
#include <gtest/gtest.h>

#include <cmath>

#include "render/frame_scene.hpp"
#include "render_testing.hpp"

namespace swarmagg {
namespace {

using testing::Swarm;

FrameLayout fit(const WorldSpec& spec, int size = 400) {
  return make_frame_layout(size, size, spec.arena);
}

// Three agents away from the seam: one in each of GO, LEAVE, and a WAIT pair (aggregate 0).
Swarm three_states(const WorldSpec& spec) {
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(10, 10, AgentState::Go);
  swarm.add(20, 20, AgentState::Leave);
  swarm.add(30, 30, AgentState::Wait, 0);
  swarm.add(31.5, 30, AgentState::Wait, 0);
  return swarm;
}

TEST(SceneOptions, DefaultsAreTheFrameOfARun) {
  const WorldSpec spec = testing::tiny_world();
  const Swarm swarm = testing::random_swarm(spec, 60, 0.4);
  FrameSceneBuilder a;
  FrameSceneBuilder b;
  const FrameScene& plain = a.build(swarm.snapshot(), fit(spec));
  const FrameScene& options = b.build(swarm.snapshot(), fit(spec), SceneOptions{});
  ASSERT_EQ(plain.bodies.size(), options.bodies.size());
  EXPECT_EQ(plain.rings.size(), options.rings.size());
  EXPECT_EQ(plain.links.size(), options.links.size());
  EXPECT_TRUE(options.marks.empty());
  EXPECT_TRUE(SceneOptions{}.fits());
}

TEST(SceneOptions, ColoursBodiesByStateAggregateOrSize) {
  const WorldSpec spec = testing::tiny_world();
  const Swarm swarm = three_states(spec);
  FrameSceneBuilder builder;
  SceneOptions options;
  const FrameScene& by_state = builder.build(swarm.snapshot(), fit(spec), options);
  EXPECT_EQ(by_state.bodies[0].fill, palette::kGo);
  EXPECT_EQ(by_state.bodies[1].fill, palette::kLeave);
  EXPECT_EQ(by_state.bodies[2].fill, palette::kWait);

  options.colour = ColourMode::Aggregate;
  const FrameScene& by_aggregate = builder.build(swarm.snapshot(), fit(spec), options);
  EXPECT_EQ(by_aggregate.bodies[0].fill, palette::kUnaggregated);
  EXPECT_EQ(by_aggregate.bodies[2].fill, palette::aggregate_colour(2));  // lowest member 2
  EXPECT_EQ(by_aggregate.bodies[3].fill, by_aggregate.bodies[2].fill);

  options.colour = ColourMode::Size;
  const FrameScene& by_size = builder.build(swarm.snapshot(), fit(spec), options);
  EXPECT_EQ(by_size.bodies[1].fill, palette::kUnaggregated);
  EXPECT_EQ(by_size.bodies[2].fill, palette::size_colour(2, 4));
  EXPECT_NE(palette::size_colour(2, 100), palette::size_colour(50, 100));
  EXPECT_EQ(palette::size_colour(100, 100), palette::size_colour(60, 100));  // last bucket
}

TEST(SceneOptions, RingRadiiAreTheDetectionAndApproachRadii) {
  WorldSpec spec = testing::tiny_world();
  spec.controller.approach_radius = 9.0;
  const Swarm swarm = three_states(spec);
  const FrameLayout layout = fit(spec);
  FrameSceneBuilder builder;
  SceneOptions options;
  options.detection = OverlayScope::Selected;
  options.approach = OverlayScope::Selected;
  options.selected = 1;
  const FrameScene& scene = builder.build(swarm.snapshot(), layout, options);
  ASSERT_EQ(scene.rings.size(), 2u);
  const float line = scene.rings[0].line;
  EXPECT_NEAR(scene.rings[0].radius, 4.0 * layout.scale + line / 2, 1e-4);
  EXPECT_NEAR(scene.rings[1].radius, 9.0 * layout.scale + line / 2, 1e-4);
  EXPECT_NEAR(scene.rings[0].x, layout.to_pixel({20, 20}).x, 1e-3);
  ASSERT_EQ(scene.marks.size(), 1u);
  EXPECT_GT(scene.marks[0].radius, scene.bodies[1].radius);

  options.detection = OverlayScope::All;
  options.approach = OverlayScope::None;
  EXPECT_EQ(builder.build(swarm.snapshot(), layout, options).rings.size(), 4u);
  options.detection = OverlayScope::None;
  EXPECT_TRUE(builder.build(swarm.snapshot(), layout, options).rings.empty());
}

TEST(SceneOptions, TextIsPartOfTheScene) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm = three_states(spec);
  swarm.step = 42;
  FrameSceneBuilder builder;
  SceneOptions options;
  const FrameScene& plain = builder.build(swarm.snapshot(), fit(spec), options);
  ASSERT_FALSE(plain.labels.empty());
  EXPECT_EQ(plain.labels[0].text, "T=0  STEP=42  NOA=1");
  EXPECT_EQ(plain.labels.size(), 4u);  // caption and GO, WAIT, LEAVE (no APPROACH: Bayindir)
  EXPECT_EQ(plain.rects.size(), 6u);   // each legend swatch: outline and fill
  options.selected = 1;
  const FrameScene& selected = builder.build(swarm.snapshot(), fit(spec), options);
  ASSERT_EQ(selected.labels.size(), 5u);
  EXPECT_EQ(selected.labels.back().text, "1");
  EXPECT_GT(selected.labels.back().x, selected.marks[0].x);  // to the right of the agent
}

TEST(SceneOptions, TorusGhostsCanBeSwitchedOff) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(1.0, 1.0, AgentState::Go);  // a corner: four copies
  FrameSceneBuilder builder;
  SceneOptions options;
  EXPECT_EQ(builder.build(swarm.snapshot(), fit(spec), options).bodies.size(), 4u);
  options.ghosts = false;
  EXPECT_EQ(builder.build(swarm.snapshot(), fit(spec), options).bodies.size(), 1u);
  // The approach circle reaches farther, so it brings copies of agents farther in.
  Swarm inner;
  inner.spec = &spec;
  inner.add(8.0, 20.0);
  options.ghosts = true;
  EXPECT_EQ(builder.build(inner.snapshot(), fit(spec), options).bodies.size(), 1u);
  options.approach = OverlayScope::All;  // s_a = 12 by default
  EXPECT_EQ(builder.build(inner.snapshot(), fit(spec), options).bodies.size(), 2u);
}

TEST(SceneOptions, NeighbourLinksContactsAndTrailsAreSegments) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(10, 10);
  swarm.add(13, 10);    // 3 from the first: neighbours (s = 4), not touching (2r = 2)
  swarm.add(14.9, 10);  // 1.9 from the second: touching
  FrameSceneBuilder builder;
  SceneOptions options;
  options.links = false;
  EXPECT_TRUE(builder.build(swarm.snapshot(), fit(spec), options).links.empty());
  options.neighbour_links = true;
  EXPECT_EQ(builder.build(swarm.snapshot(), fit(spec), options).links.size(), 2u);
  options.neighbour_links = false;
  options.contacts = true;
  const FrameScene& contacts = builder.build(swarm.snapshot(), fit(spec), options);
  ASSERT_EQ(contacts.links.size(), 1u);
  EXPECT_EQ(contacts.links[0].colour, palette::kContact);

  options.contacts = false;
  options.trails = true;
  // Two past frames: agent 0 crossed the seam (x 39.5 -> 0.5): its trail segment is 1 long.
  std::vector<Vec2> trail{{39.5, 5}, {13, 10}, {14.9, 10}, {0.5, 5}, {13, 11}, {14.9, 11}};
  const FrameLayout layout = fit(spec);
  const FrameScene& trails = builder.build(swarm.snapshot(), layout, options, {trail, 2});
  ASSERT_EQ(trails.links.size(), 3u);
  EXPECT_NEAR(
      std::hypot(trails.links[0].x1 - trails.links[0].x0, trails.links[0].y1 - trails.links[0].y0),
      1.0 * layout.scale, 1e-3);
}

TEST(SceneOptions, ZoomMagnifiesAboutTheCentre) {
  const WorldSpec spec = testing::tiny_world();
  const FrameLayout layout = fit(spec);
  SceneOptions options;
  options.zoom = 2.0;
  options.centre = Vec2{10, 10};
  const FrameLayout zoomed = FrameSceneBuilder::layout_for(layout, options);
  EXPECT_DOUBLE_EQ(zoomed.scale, 2 * layout.scale);
  const PixelRect view = layout.view();
  const Vec2 centre = zoomed.to_pixel({10, 10});
  EXPECT_NEAR(centre.x, view.left + view.width / 2.0, 1e-9);
  EXPECT_NEAR(centre.y, view.top + view.height / 2.0, 1e-9);
  EXPECT_GE(zoomed.arena.top, layout.header_height);  // clipped below the header
  const Vec2 back = zoomed.to_arena(zoomed.to_pixel({3.25, 7.5}));
  EXPECT_NEAR(back.x, 3.25, 1e-9);
  EXPECT_NEAR(back.y, 7.5, 1e-9);
}

TEST(PickAgent, FindsTheAgentUnderAPixelAcrossTheSeam) {
  const WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(20, 20);
  swarm.add(39.6, 20);  // its body (r = 1) wraps past x = 40 onto x = 0..0.6
  swarm.add(-0.5, 5);   // stored outside the arena: drawn at x = 39.5
  const FrameLayout layout = fit(spec);
  const auto pixel = [&](double x, double y) { return layout.to_pixel({x, y}); };
  EXPECT_EQ(pick_agent(swarm.snapshot(), layout, pixel(20.3, 20.2)), 0);
  EXPECT_EQ(pick_agent(swarm.snapshot(), layout, pixel(30, 30), 0.0f), -1);
  EXPECT_EQ(pick_agent(swarm.snapshot(), layout, pixel(0.2, 20)), 1);  // the ghost on the left
  EXPECT_EQ(pick_agent(swarm.snapshot(), layout, pixel(39.5, 5)), 2);
  // Nearest wins when two bodies are within reach.
  swarm.add(21.5, 20);
  EXPECT_EQ(pick_agent(swarm.snapshot(), layout, pixel(21.2, 20)), 3);
  // With walls nothing is picked outside the arena.
  const WorldSpec walled = testing::tiny_world(40, 40, Topology::Walls);
  Swarm inside;
  inside.spec = &walled;
  inside.add(0.5, 20);
  const FrameLayout walled_layout = fit(walled);
  EXPECT_EQ(pick_agent(inside.snapshot(), walled_layout, walled_layout.to_pixel({0.2, 20})), 0);
  EXPECT_EQ(pick_agent(inside.snapshot(), walled_layout, walled_layout.to_pixel({39.9, 20})), -1);
}

}  // namespace
}  // namespace swarmagg
