#pragma once
// Where the S key's screenshot goes: `<world>-step<N>.png` in the working folder, or, when a
// file of that name is already there (a reset, a zoom or another replicate at the same step),
// the first of `<world>-step<N>-2.png`, `-3`, ... that is not, so that no earlier screenshot
// is overwritten.
#include <cstdint>
#include <filesystem>
#include <string>

namespace swarmagg {

std::filesystem::path unused_screenshot_path(const std::filesystem::path& folder,
                                             const std::string& world, std::int64_t step);

}  // namespace swarmagg
