#include "rates/rates_origin.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "config/world_difference.hpp"
#include "control_interface/controller_rules.hpp"
#include "controllers/controller_registry.hpp"

namespace swarmagg {
namespace {

std::string world_doubt(const std::filesystem::path& rates_csv, const WorldSpec& world) {
  const std::filesystem::path json_file = rates_csv.parent_path() / "rates.json";
  const RatesJsonWorld recorded = rates_json_world(json_file);
  if (recorded.found == RatesJsonWorld::Found::None) {
    return "no rates.json beside it records the world they were measured in (rates.csv copied "
           "alone, or written by hand): that they come from this world is not checked";
  }
  if (recorded.found == RatesJsonWorld::Found::Unreadable) {
    return json_file.string() +
           " beside it cannot be read: which world these rates come from "
           "is unknown";
  }
  const std::vector<std::string> differences = system_differences(recorded.resolved_world, world);
  if (differences.empty()) return "";
  return "it was measured in another world (" + differences_text(differences) +
         "): the measured variants feed its terms into this world's model";
}

std::string model_doubt(const std::vector<RateRow>& rows, const WorldSpec& world) {
  const ModelFamily family = controller_rules(world).model;
  if (family != ModelFamily::Bayindir && family != ModelFamily::Soysal) return "";
  const std::string ours = family == ModelFamily::Soysal ? "soysal" : "bayindir";
  std::string theirs;
  for (const RateRow& row : rows) {
    for (const ModelTerm& term : row.models) {
      if (term.model == ours) return "";
      theirs = term.model;
    }
  }
  if (theirs.empty()) return "";
  return "its rows were written for the " + theirs + " model, this world's is the " + ours +
         " model";
}

}  // namespace

RatesJsonWorld rates_json_world(const std::filesystem::path& json_file) {
  std::ifstream in(json_file);
  if (!in) return {};
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.is_object()) return {RatesJsonWorld::Found::Unreadable, ""};
  if (!json.contains("resolved_world") || !json["resolved_world"].is_string()) return {};
  return {RatesJsonWorld::Found::World, json["resolved_world"].get<std::string>()};
}

std::vector<std::string> rates_origin_doubts(const std::filesystem::path& rates_csv,
                                             const std::vector<RateRow>& rows,
                                             const WorldSpec& world) {
  std::vector<std::string> doubts;
  for (const std::string& doubt : {world_doubt(rates_csv, world), model_doubt(rows, world)}) {
    if (!doubt.empty()) doubts.push_back(doubt);
  }
  return doubts;
}

}  // namespace swarmagg
