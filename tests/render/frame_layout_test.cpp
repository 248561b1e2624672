#include "render/frame_layout.hpp"

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "render/render_size.hpp"

namespace swarmagg {
namespace {

ArenaSpec arena(double w, double h) {
  ArenaSpec a;
  a.width = w;
  a.height = h;
  return a;
}

TEST(FrameLayout, SquareArenaFitsBelowTheHeaderCentred) {
  const FrameLayout l = make_frame_layout(800, 800, arena(180, 180));
  EXPECT_EQ(l.text_scale, 2);
  EXPECT_EQ(l.header_height, 26);
  EXPECT_DOUBLE_EQ(l.scale, 774.0 / 180.0);
  EXPECT_EQ(l.arena.top, 26);
  EXPECT_EQ(l.arena.left, 13);
  EXPECT_EQ(l.arena.width, 774);
  EXPECT_EQ(l.arena.height, 774);
  const Vec2 top_left = l.to_pixel({0, 180});
  EXPECT_DOUBLE_EQ(top_left.x, 13.0);
  EXPECT_DOUBLE_EQ(top_left.y, 26.0);
  const Vec2 bottom_right = l.to_pixel({180, 0});
  EXPECT_NEAR(bottom_right.x, 13.0 + 774.0, 1e-9);
  EXPECT_NEAR(bottom_right.y, 800.0, 1e-9);
}

TEST(FrameLayout, KeepsTheAspectRatioOfAWideArena) {
  const FrameLayout l = make_frame_layout(800, 800, arena(540, 180));
  EXPECT_DOUBLE_EQ(l.scale, 800.0 / 540.0);
  EXPECT_EQ(l.arena.left, 0);
  EXPECT_EQ(l.arena.width, 800);
  EXPECT_EQ(l.arena.height, 267);           // 180 * 800 / 540 = 266.7, rounded outwards
  EXPECT_GT(l.arena.top, l.header_height);  // centred in the space below the header
  const double ratio = (l.to_pixel({540, 0}).x - l.to_pixel({0, 0}).x) /
                       (l.to_pixel({0, 0}).y - l.to_pixel({0, 180}).y);
  EXPECT_NEAR(ratio, 3.0, 1e-12);
}

TEST(FrameLayout, SmallFramesUseUnitText) {
  const FrameLayout l = make_frame_layout(200, 120, arena(10, 10));
  EXPECT_EQ(l.text_scale, 1);
  EXPECT_EQ(l.header_height, 13);
  EXPECT_DOUBLE_EQ(l.scale, 10.7);
}

TEST(FrameLayout, RejectsBadSizesAndArenas) {
  EXPECT_THROW(make_frame_layout(31, 800, arena(10, 10)), InputError);
  EXPECT_THROW(make_frame_layout(800, kMaxRenderSide + 1, arena(10, 10)), InputError);
  EXPECT_THROW(make_frame_layout(800, 800, arena(0, 10)), InputError);
  EXPECT_THROW(make_frame_layout(800, 800, arena(10, -1)), InputError);
}

TEST(RenderSize, ParsesWidthByHeight) {
  EXPECT_EQ(parse_render_size("800x600"), (RenderSize{800, 600}));
  EXPECT_EQ(parse_render_size("64X32"), (RenderSize{64, 32}));
  for (const char* bad : {"", "800", "800x", "x600", "800x600x2", "-800x600", "80 0x600",
                          "800x600px", "10x10", "100000x100"}) {
    EXPECT_THROW(parse_render_size(bad), InputError) << bad;
  }
}

}  // namespace
}  // namespace swarmagg
