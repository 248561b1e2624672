#pragma once
// "1 replicate", "4 replicates": a count and its noun, in the plural unless the count is one.
#include <string>
#include <string_view>

namespace swarmagg {

inline std::string counted(long long count, std::string_view noun) {
  return std::to_string(count) + " " + std::string(noun) + (count == 1 ? "" : "s");
}

}  // namespace swarmagg
