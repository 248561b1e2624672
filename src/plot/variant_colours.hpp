#pragma once
// One colour per model variant, in the order a plot lists them, shared by every plot so a
// variant looks the same everywhere: Bayindir's original blue and the collision variants
// orange as the paper colours them, then further colour-blind-safe Okabe-Ito hues.
#include <array>
#include <cstddef>
#include <string>

namespace swarmagg {

inline std::string variant_colour(std::size_t index) {
  static constexpr std::array<const char*, 6> kColours{"#1f77b4", "#ff7f0e", "#009e73",
                                                       "#cc79a7", "#56b4e9", "#e69f00"};
  return kColours[index % kColours.size()];
}

}  // namespace swarmagg
