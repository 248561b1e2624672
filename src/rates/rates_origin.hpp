#pragma once
// Where measured rates came from: the world recorded in the rates.json beside a rates.csv. A
// model fed rates measured in another system (another arena, swarm, controller or engine)
// mixes two worlds; that can be meant (rates carried over on purpose), so it is said, not
// refused.
#include <filesystem>
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

// The keys in which the world of `rates_csv` (its sibling rates.json's resolved_world) differs
// from `world` (config/world_difference.hpp); empty when they match or when no rates.json
// with a resolved world lies beside it (rates of older versions, or copied alone).
std::vector<std::string> rates_world_differences(const std::filesystem::path& rates_csv,
                                                 const WorldSpec& world);

}  // namespace swarmagg
