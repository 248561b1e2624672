#pragma once
// Suggests the closest known name for a misspelt one (edit distance), for error messages.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swarmagg {

std::optional<std::string> closest_name(std::string_view wrong,
                                        const std::vector<std::string>& known);

}  // namespace swarmagg
