#include "rates/rates_origin.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "config/world_difference.hpp"

namespace swarmagg {

std::vector<std::string> rates_world_differences(const std::filesystem::path& rates_csv,
                                                 const WorldSpec& world) {
  std::ifstream in(rates_csv.parent_path() / "rates.json");
  if (!in) return {};
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.contains("resolved_world") ||
      !json["resolved_world"].is_string())
    return {};
  return system_differences(json["resolved_world"].get<std::string>(), world);
}

}  // namespace swarmagg
