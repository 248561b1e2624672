#pragma once
// The comparison as a short text for people (stdout and summary.txt) and as JSON
// (compare.json) for programs; both say the same things.
#include <nlohmann/json.hpp>
#include <string>

#include "compare/arm_comparison.hpp"

namespace swarmagg {

std::string comparison_text(const std::string& world_name, const Comparison& c);
nlohmann::json comparison_json(const std::string& world_name, const Comparison& c);

}  // namespace swarmagg
