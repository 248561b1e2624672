#pragma once
// What a benchmark ran on, so figures from different machines are never mixed up.
#include <nlohmann/json.hpp>

namespace swarmagg {

nlohmann::json machine_info();

}  // namespace swarmagg
