#pragma once
// Where measured rates came from: the world recorded in the rates.json beside a rates.csv, and
// the model its rows were written for. A model fed rates measured in another system (another
// arena, swarm, controller or engine) mixes two worlds; that can be meant (rates carried over
// on purpose), so it is said, not refused.
#include <filesystem>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "rates/rate_rows.hpp"

namespace swarmagg {

// One sentence per reason to doubt that `rows` (read from `rates_csv`) belong to `world`: its
// sibling rates.json records another world (config/world_difference.hpp) or cannot be read,
// or the rows were written for the other model (Soysal's pairup/join against Bayindir's
// creation/growth). Empty when nothing says so, as for rates copied without their rates.json.
std::vector<std::string> rates_origin_doubts(const std::filesystem::path& rates_csv,
                                             const std::vector<RateRow>& rows,
                                             const WorldSpec& world);

}  // namespace swarmagg
