#include "render/frame_renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.hpp"
#include "render/palette.hpp"
#include "render_testing.hpp"

namespace swarmagg {
namespace {

using testing::distance;
using testing::over;
using testing::pixel;
using testing::pixel_at;
using testing::Swarm;

// Four agents, one per state, one per quadrant of a 40 x 40 torus.
struct QuadrantWorld {
  WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  QuadrantWorld() {
    swarm.spec = &spec;
    swarm.add(10, 10, AgentState::Go);
    swarm.add(30, 10, AgentState::Wait);
    swarm.add(10, 30, AgentState::Leave);
    swarm.add(30, 30, AgentState::Approach);
  }
};

// The darkest pixel on the ray from `centre` along +x between two radii (arena units).
Rgba8 darkest_on_ray(std::span<const std::uint8_t> rgba, const FrameLayout& layout, Vec2 centre,
                     double from, double to) {
  const Vec2 c = layout.to_pixel(centre);
  const int row = static_cast<int>(c.y);
  Rgba8 best{255, 255, 255, 255};
  for (int col = static_cast<int>(c.x + from * layout.scale);
       col <= static_cast<int>(c.x + to * layout.scale); ++col) {
    const Rgba8 p = pixel(rgba, layout.width, col, row);
    if (p.r + p.g + p.b < best.r + best.g + best.b) best = p;
  }
  return best;
}

TEST(FrameRenderer, FillsEveryAgentCentreWithItsStateColour) {
  QuadrantWorld world;
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(world.swarm.snapshot());
  ASSERT_EQ(frame.size(), 200u * 200u * 4u);
  const FrameLayout layout = renderer.layout(world.spec.arena);
  EXPECT_EQ(pixel_at(frame, layout, {10, 10}), palette::kGo);
  EXPECT_EQ(pixel_at(frame, layout, {30, 10}), palette::kWait);
  EXPECT_EQ(pixel_at(frame, layout, {10, 30}), palette::kLeave);
  EXPECT_EQ(pixel_at(frame, layout, {30, 30}), palette::kApproach);
}

TEST(FrameRenderer, ArenaYPointsUpAndRowsComeTopDown) {
  QuadrantWorld world;
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(world.swarm.snapshot());
  // (10, 30) is high in the arena, so near the top of the picture: upper-left quadrant.
  const FrameLayout layout = renderer.layout(world.spec.arena);
  const int mid_col = layout.arena.left + layout.arena.width / 2;
  const int mid_row = layout.arena.top + layout.arena.height / 2;
  const Vec2 leave = layout.to_pixel({10, 30});
  EXPECT_LT(leave.x, mid_col);
  EXPECT_LT(leave.y, mid_row);
  EXPECT_EQ(pixel(frame, 200, static_cast<int>(leave.x), static_cast<int>(leave.y)),
            palette::kLeave);
  // Raw row 0 of the buffer is the header band, not the arena.
  EXPECT_EQ(pixel(frame, 200, 199, 0), palette::kMargin);
}

TEST(FrameRenderer, PaintsFloorMarginAndHeader) {
  QuadrantWorld world;
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(world.swarm.snapshot());
  const FrameLayout layout = renderer.layout(world.spec.arena);
  EXPECT_EQ(pixel_at(frame, layout, {20, 20}), palette::kArena);  // far from every agent
  EXPECT_EQ(pixel_at(frame, layout, {2, 38}), palette::kArena);
  ASSERT_GT(layout.arena.left, 0);  // a square arena in a portrait band leaves side margins
  EXPECT_EQ(pixel(frame, 200, 0, 100), palette::kMargin);
  EXPECT_EQ(pixel(frame, 200, 199, 100), palette::kMargin);
  // The caption is written in the header band.
  int text_pixels = 0;
  for (int row = 0; row < layout.header_height; ++row) {
    for (int col = 0; col < 200; ++col)
      text_pixels += pixel(frame, 200, col, row) == palette::kText;
  }
  EXPECT_GT(text_pixels, 20);
}

TEST(FrameRenderer, DrawsTheDetectionCircleThin) {
  QuadrantWorld world;
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(world.swarm.snapshot());
  const FrameLayout layout = renderer.layout(world.spec.arena);
  const double s = world.spec.robots.detection_radius;
  const Rgba8 full = over(palette::kDetection, palette::kArena);
  for (const Vec2 centre : {Vec2{10, 10}, Vec2{30, 10}, Vec2{10, 30}, Vec2{30, 30}}) {
    const Rgba8 ring = darkest_on_ray(frame, layout, centre, s - 0.3, s + 0.3);
    SCOPED_TRACE(testing::describe(ring));
    EXPECT_EQ(ring.r, ring.g);  // grey
    EXPECT_EQ(ring.g, ring.b);
    EXPECT_LE(distance(ring, full), 3 * 48);  // at least half covered
    EXPECT_LT(ring.r, palette::kArena.r - 40);
    // Inside the circle, between body and ring, the floor shows: a ring, not a disc.
    EXPECT_EQ(pixel_at(frame, layout, centre + Vec2{s / 2 + 0.3, 0}), palette::kArena);
    EXPECT_EQ(pixel_at(frame, layout, centre + Vec2{s + 0.6, 0}), palette::kArena);
  }
}

TEST(FrameRenderer, SameStateGivesIdenticalBytes) {
  const WorldSpec spec = testing::tiny_world(180, 180);
  const Swarm swarm = testing::random_swarm(spec, 300, 0.3);
  QuadrantWorld other;
  FrameRenderer renderer(320, 240);
  const auto drawn = renderer.render(swarm.snapshot());
  const std::vector<std::uint8_t> first(drawn.begin(), drawn.end());
  renderer.render(other.swarm.snapshot());  // something else in between
  const auto again = renderer.render(swarm.snapshot());
  EXPECT_TRUE(std::equal(first.begin(), first.end(), again.begin(), again.end()));
  FrameRenderer fresh(320, 240);  // and a second context agrees
  const auto third = fresh.render(swarm.snapshot());
  EXPECT_TRUE(std::equal(first.begin(), first.end(), third.begin(), third.end()));
}

TEST(FrameRenderer, WorksWithDisplayUnset) {
  const char* old = std::getenv("DISPLAY");
  const std::optional<std::string> saved = old ? std::optional<std::string>(old) : std::nullopt;
  ::unsetenv("DISPLAY");
  QuadrantWorld world;
  {
    FrameRenderer renderer(200, 200);
    const auto frame = renderer.render(world.swarm.snapshot());
    EXPECT_EQ(pixel_at(frame, renderer.layout(world.spec.arena), {10, 10}), palette::kGo);
  }
  ::setenv("DISPLAY", ":4242", 1);  // a display that does not exist changes nothing either
  {
    FrameRenderer renderer(200, 200);
    const auto frame = renderer.render(world.swarm.snapshot());
    EXPECT_EQ(pixel_at(frame, renderer.layout(world.spec.arena), {30, 10}), palette::kWait);
  }
  if (saved) {
    ::setenv("DISPLAY", saved->c_str(), 1);
  } else {
    ::unsetenv("DISPLAY");
  }
}

TEST(FrameRenderer, DrawsAgentsStraddlingTheTorusSeamOnBothSides) {
  WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(0.3, 20, AgentState::Go);      // across the left/right seam
  swarm.add(20, 39.7, AgentState::Leave);  // across the top/bottom seam
  swarm.add(39.8, 0.2, AgentState::Wait);  // across the corner
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(swarm.snapshot());
  const FrameLayout layout = renderer.layout(spec.arena);
  EXPECT_EQ(pixel_at(frame, layout, {0.3, 20}), palette::kGo);
  EXPECT_EQ(pixel_at(frame, layout, {39.8, 20}), palette::kGo);  // 0.5 units left of the copy
  EXPECT_EQ(pixel_at(frame, layout, {20, 39.7}), palette::kLeave);
  EXPECT_EQ(pixel_at(frame, layout, {20, 0.2}), palette::kLeave);
  for (const Vec2 corner : {Vec2{39.8, 0.2}, Vec2{0.1, 0.2}, Vec2{39.8, 39.9}, Vec2{0.1, 39.9}}) {
    SCOPED_TRACE(std::to_string(corner.x) + "," + std::to_string(corner.y));
    EXPECT_EQ(pixel_at(frame, layout, corner), palette::kWait);
  }
  // The detection circle wraps too: the first agent's circle crosses x = 40 - 3.7.
  const Rgba8 ring = darkest_on_ray(frame, layout, {40.3 - 4.0, 20}, -0.3, 0.3);
  EXPECT_LT(ring.r, palette::kArena.r - 40) << testing::describe(ring);
}

TEST(FrameRenderer, WallsHaveNoWrapCopiesButABorder) {
  WorldSpec spec = testing::tiny_world(40, 40, Topology::Walls);
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(0.3, 20, AgentState::Go);
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(swarm.snapshot());
  const FrameLayout layout = renderer.layout(spec.arena);
  EXPECT_EQ(pixel_at(frame, layout, {1.0, 20}), palette::kGo);
  EXPECT_EQ(pixel_at(frame, layout, {39.0, 20}), palette::kArena);
  // The wall is drawn on the arena's edge.
  const Vec2 edge = layout.to_pixel({40, 10});
  EXPECT_EQ(pixel(frame, 200, static_cast<int>(edge.x) - 1, static_cast<int>(edge.y)),
            palette::kWall);
}

TEST(FrameRenderer, GroupsAggregateMembersWithATintAndLinks) {
  WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  swarm.add(20, 20, AgentState::Wait, 0);
  swarm.add(23, 20, AgentState::Wait, 0);
  swarm.add(20, 30, AgentState::Go);  // two agents within s, but not an aggregate
  swarm.add(23, 30, AgentState::Go);
  FrameRenderer renderer(200, 200);
  const auto frame = renderer.render(swarm.snapshot());
  const FrameLayout layout = renderer.layout(spec.arena);
  const Rgba8 tint = palette::aggregate_tint(0);
  // Between the members: the link, a dark grey line over the tint.
  const Vec2 middle = layout.to_pixel({21.5, 20});
  Rgba8 link = tint;
  for (int row = static_cast<int>(middle.y) - 2; row <= static_cast<int>(middle.y) + 2; ++row) {
    const Rgba8 p = pixel(frame, layout.width, static_cast<int>(middle.x), row);
    if (p.r + p.g + p.b < link.r + link.g + link.b) link = p;
  }
  const Rgba8 full = over(palette::kLink, tint);
  EXPECT_LT(link.r + link.g + link.b, (full.r + full.g + full.b + tint.r + tint.g + tint.b) / 2)
      << testing::describe(link);
  // Beside the link, still within s/2 of both members: the tint alone.
  EXPECT_EQ(pixel_at(frame, layout, {21.5, 20.8}), tint);
  // The non-aggregated pair has neither.
  for (double dy = -0.4; dy <= 0.4; dy += 0.1) {
    EXPECT_EQ(pixel_at(frame, layout, {21.5, 30 + dy}), palette::kArena);
  }
  EXPECT_EQ(pixel_at(frame, layout, {21.5, 30.8}), palette::kArena);
}

TEST(FrameRenderer, RendersFromAnotherThread) {
  QuadrantWorld world;
  FrameRenderer renderer(200, 200);
  renderer.render(world.swarm.snapshot());
  Rgba8 centre;
  std::thread worker([&] {
    const auto frame = renderer.render(world.swarm.snapshot());
    centre = pixel_at(frame, renderer.layout(world.spec.arena), {30, 30});
  });
  worker.join();
  EXPECT_EQ(centre, palette::kApproach);
  EXPECT_EQ(pixel_at(renderer.render(world.swarm.snapshot()), renderer.layout(world.spec.arena),
                     {30, 30}),
            palette::kApproach);
}

TEST(FrameRenderer, RenderersOnSeveralThreadsAtOnceAgree) {
  const WorldSpec spec = testing::tiny_world(120, 120);
  const Swarm swarm = testing::random_swarm(spec, 200, 0.3);
  FrameRenderer reference(160, 160);
  const auto expected = reference.render(swarm.snapshot());
  const std::vector<std::uint8_t> want(expected.begin(), expected.end());
  std::vector<int> mismatches(3, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t) {
    threads.emplace_back([&, t] {
      FrameRenderer renderer(160, 160);
      for (int f = 0; f < 20; ++f) {
        const auto frame = renderer.render(swarm.snapshot());
        mismatches[t] += !std::equal(frame.begin(), frame.end(), want.begin(), want.end());
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(mismatches, (std::vector<int>{0, 0, 0}));
}

TEST(FrameRenderer, CopiesIntoACallerBufferOfTheRightSize) {
  QuadrantWorld world;
  FrameRenderer renderer(200, 100);
  std::vector<std::uint8_t> out(200 * 100 * 4);
  renderer.render(world.swarm.snapshot(), out);
  const auto direct = renderer.render(world.swarm.snapshot());
  EXPECT_TRUE(std::equal(out.begin(), out.end(), direct.begin(), direct.end()));
  std::vector<std::uint8_t> wrong(200 * 100 * 3);
  EXPECT_THROW(renderer.render(world.swarm.snapshot(), wrong), std::invalid_argument);
}

TEST(FrameRenderer, RejectsBadSizesAndSnapshots) {
  EXPECT_THROW(FrameRenderer(8, 800), InputError);
  EXPECT_THROW(FrameRenderer(800, 100000), InputError);
  FrameRenderer renderer(64, 64);
  SwarmSnapshot no_spec;
  EXPECT_THROW(renderer.render(no_spec), std::invalid_argument);
}

TEST(FrameRenderer, EmptySwarmIsJustTheFloor) {
  WorldSpec spec = testing::tiny_world();
  Swarm swarm;
  swarm.spec = &spec;
  FrameRenderer renderer(100, 100);
  const auto frame = renderer.render(swarm.snapshot());
  const FrameLayout layout = renderer.layout(spec.arena);
  EXPECT_EQ(pixel_at(frame, layout, {20, 20}), palette::kArena);
}

}  // namespace
}  // namespace swarmagg
