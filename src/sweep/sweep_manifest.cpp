#include "sweep/sweep_manifest.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/errors.hpp"

namespace swarmagg {

std::string manifest_text(const SweepPlan& plan) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const SweepParameter& p : plan.parameters)
    parameters.push_back({{"key", p.key}, {"values", p.values}});
  const nlohmann::json manifest = {{"name", plan.name},
                                   {"seed", plan.seed},
                                   {"replicates", plan.replicates},
                                   {"parameters", parameters},
                                   {"base_world", plan.base_world}};
  return manifest.dump(2) + "\n";
}

SweepPlan read_manifest(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / kManifestFile;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(folder.string() + ": not a sweep output folder (no " + kManifestFile + ")");
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json manifest = nlohmann::json::parse(text.str());
    SweepPlan plan;
    plan.source = path.string();
    plan.name = manifest.at("name").get<std::string>();
    plan.seed = manifest.at("seed").get<std::uint64_t>();
    plan.replicates = manifest.at("replicates").get<int>();
    plan.base_world = manifest.at("base_world").get<std::string>();
    for (const nlohmann::json& p : manifest.at("parameters")) {
      plan.parameters.push_back(
          {p.at("key").get<std::string>(), p.at("values").get<std::vector<std::string>>()});
    }
    return plan;
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": not a valid sweep manifest: " + e.what());
  }
}

}  // namespace swarmagg
