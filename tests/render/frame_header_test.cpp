#include "render/frame_header.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "render/bitmap_font.hpp"
#include "render_testing.hpp"

namespace swarmagg {
namespace {

TEST(FrameHeader, CaptionGivesTimeStepAndNoa) {
  const WorldSpec spec = testing::tiny_world();
  testing::Swarm swarm;
  swarm.spec = &spec;
  swarm.step = 3;
  swarm.time = 0.1 * 3;  // 0.30000000000000004 prints as 0.3
  swarm.noa = 7;
  EXPECT_EQ(frame_caption(swarm.snapshot()), "T=0.3  STEP=3  NOA=7");
  swarm.step = 12345678;
  swarm.time = 1234567.8;
  EXPECT_EQ(frame_caption(swarm.snapshot()), "T=1234567.8  STEP=12345678  NOA=7");
}

int count_colour(const std::vector<std::uint8_t>& rgba, Rgba8 c) {
  int n = 0;
  for (std::size_t o = 0; o < rgba.size(); o += 4) {
    n += rgba[o] == c.r && rgba[o + 1] == c.g && rgba[o + 2] == c.b;
  }
  return n;
}

TEST(FrameHeader, LegendShowsApproachOnlyForSoysal) {
  WorldSpec spec = testing::tiny_world();
  testing::Swarm swarm;
  swarm.spec = &spec;
  const FrameLayout layout = make_frame_layout(800, 800, spec.arena);
  std::vector<std::uint8_t> rgba(800 * 800 * 4, 224);
  ASSERT_TRUE(draw_frame_header(rgba, layout, swarm.snapshot()));
  EXPECT_GT(count_colour(rgba, palette::kGo), 0);
  EXPECT_GT(count_colour(rgba, palette::kWait), 0);
  EXPECT_GT(count_colour(rgba, palette::kLeave), 0);
  EXPECT_EQ(count_colour(rgba, palette::kApproach), 0);
  spec.controller.type = "soysal";
  ASSERT_TRUE(draw_frame_header(rgba, layout, swarm.snapshot()));
  EXPECT_GT(count_colour(rgba, palette::kApproach), 0);
  // Everything stays in the header band.
  for (int row = layout.header_height; row < 800; ++row) {
    for (int col = 0; col < 800; ++col) {
      ASSERT_EQ(rgba[(static_cast<std::size_t>(row) * 800 + col) * 4], 224) << col << "," << row;
    }
  }
}

TEST(FrameHeader, DropsTheLegendWhenItDoesNotFit) {
  const WorldSpec spec = testing::tiny_world();
  testing::Swarm swarm;
  swarm.spec = &spec;
  const FrameLayout layout = make_frame_layout(120, 120, spec.arena);
  std::vector<std::uint8_t> rgba(120 * 120 * 4, 224);
  EXPECT_FALSE(draw_frame_header(rgba, layout, swarm.snapshot()));
  EXPECT_EQ(count_colour(rgba, palette::kGo), 0);
  EXPECT_GT(count_colour(rgba, palette::kText), 0);
}

}  // namespace
}  // namespace swarmagg
