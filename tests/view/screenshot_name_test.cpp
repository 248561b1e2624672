#include "view/screenshot_name.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

TEST(ScreenshotName, NeverNamesAFileThatIsAlreadyThere) {
  const testing::ScratchDir scratch("screenshot-name");
  const std::filesystem::path folder = scratch.path();
  EXPECT_EQ(unused_screenshot_path(folder, "demo", 40), folder / "demo-step40.png");
  std::ofstream(folder / "demo-step40.png") << "earlier";
  EXPECT_EQ(unused_screenshot_path(folder, "demo", 40), folder / "demo-step40-2.png");
  std::ofstream(folder / "demo-step40-2.png") << "earlier";
  EXPECT_EQ(unused_screenshot_path(folder, "demo", 40), folder / "demo-step40-3.png");
  EXPECT_EQ(unused_screenshot_path(folder, "demo", 41), folder / "demo-step41.png");
}

}  // namespace
}  // namespace swarmagg
