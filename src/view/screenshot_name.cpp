#include "view/screenshot_name.hpp"

namespace swarmagg {

std::filesystem::path unused_screenshot_path(const std::filesystem::path& folder,
                                             const std::string& world, std::int64_t step) {
  const std::string stem = world + "-step" + std::to_string(step);
  std::filesystem::path path = folder / (stem + ".png");
  for (int copy = 2; std::filesystem::exists(path); ++copy)
    path = folder / (stem + "-" + std::to_string(copy) + ".png");
  return path;
}

}  // namespace swarmagg
