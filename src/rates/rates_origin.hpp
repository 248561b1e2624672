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

// The world a rates.json records (`resolved_world`): none when the file is missing or records
// none (rates copied without it, an older version's), or the file cannot be read.
struct RatesJsonWorld {
  enum class Found { None, Unreadable, World };
  Found found = Found::None;
  std::string resolved_world;  // with Found::World
};
RatesJsonWorld rates_json_world(const std::filesystem::path& json_file);

// One sentence per reason to doubt that `rows` (read from `rates_csv`) belong to `world`: its
// sibling rates.json records another world (config/world_difference.hpp), records none (is
// missing: rates copied without it) or cannot be read, or the rows were written for the other
// model (Soysal's pairup/join against Bayindir's creation/growth).
std::vector<std::string> rates_origin_doubts(const std::filesystem::path& rates_csv,
                                             const std::vector<RateRow>& rows,
                                             const WorldSpec& world);

}  // namespace swarmagg
