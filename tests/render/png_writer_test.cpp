#include "render/png_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <vector>

#include "core/errors.hpp"
#include "render/frame_renderer.hpp"
#include "render_testing.hpp"

namespace swarmagg {
namespace {

std::vector<std::uint8_t> gradient(int w, int h, bool opaque) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t o = (static_cast<std::size_t>(y) * w + x) * 4;
      rgba[o] = static_cast<std::uint8_t>(x * 7);
      rgba[o + 1] = static_cast<std::uint8_t>(y * 13);
      rgba[o + 2] = static_cast<std::uint8_t>(x ^ y);
      rgba[o + 3] = opaque ? 255 : static_cast<std::uint8_t>(x + y);
    }
  }
  return rgba;
}

std::size_t files_in(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(WritePng, RoundTripsOpaquePixelsLosslesslyAtEveryLevel) {
  testing::ScratchDir dir("png-opaque");
  const auto pixels = gradient(37, 23, true);
  for (int level : {0, 1, 6, 9}) {
    // Appended, not "g" + std::to_string(level): see the precompiled header in
    // tests/CMakeLists.txt.
    const auto path = dir.path() / std::string("g").append(std::to_string(level)).append(".png");
    write_png(path, 37, 23, pixels, level);
    const testing::Image image = testing::read_png(path);
    EXPECT_EQ(image.width, 37);
    EXPECT_EQ(image.height, 23);
    EXPECT_EQ(image.rgba, pixels) << "level " << level;
  }
  EXPECT_EQ(files_in(dir.path()), 4u);  // no temporary files left behind
}

TEST(WritePng, KeepsAlphaWhenTheImageIsNotOpaque) {
  testing::ScratchDir dir("png-alpha");
  const auto pixels = gradient(16, 16, false);
  write_png(dir.path() / "a.png", 16, 16, pixels, 1);
  EXPECT_EQ(testing::read_png(dir.path() / "a.png").rgba, pixels);
}

TEST(WritePng, ARenderedFrameDecodesToTheSamePixels) {
  testing::ScratchDir dir("png-frame");
  const WorldSpec spec = testing::tiny_world(180, 180);
  const testing::Swarm swarm = testing::random_swarm(spec, 150, 0.3);
  FrameRenderer renderer(300, 200);
  const auto frame = renderer.render(swarm.snapshot());
  const auto path = dir.path() / "sub" / "frame.png";  // parent directories are created
  write_png(path, 300, 200, frame, 1);
  const testing::Image image = testing::read_png(path);
  ASSERT_EQ(image.width, 300);
  ASSERT_EQ(image.height, 200);
  EXPECT_TRUE(std::equal(frame.begin(), frame.end(), image.rgba.begin(), image.rgba.end()));
}

TEST(WritePng, ReplacesAnExistingFileWhole) {
  testing::ScratchDir dir("png-replace");
  const auto path = dir.path() / "f.png";
  { std::ofstream(path) << "not a png"; }
  write_png(path, 8, 8, gradient(8, 8, true), 1);
  EXPECT_EQ(testing::read_png(path).width, 8);
}

TEST(WritePng, RejectsBadArguments) {
  testing::ScratchDir dir("png-bad");
  const auto pixels = gradient(8, 8, true);
  EXPECT_THROW(write_png(dir.path() / "x.png", 8, 8, pixels, 10), InputError);
  EXPECT_THROW(write_png(dir.path() / "x.png", 8, 8, pixels, -1), InputError);
  EXPECT_THROW(write_png(dir.path() / "x.png", 8, 9, pixels, 1), std::invalid_argument);
  EXPECT_THROW(write_png(dir.path() / "x.png", 0, 0, {}, 1), std::invalid_argument);
  // A file where the directory should be.
  { std::ofstream(dir.path() / "blocker") << "x"; }
  EXPECT_ANY_THROW(write_png(dir.path() / "blocker" / "x.png", 8, 8, pixels, 1));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.png"));
}

}  // namespace
}  // namespace swarmagg
