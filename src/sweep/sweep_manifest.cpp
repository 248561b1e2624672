#include "sweep/sweep_manifest.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "config/world_keys.hpp"
#include "config/world_spec.hpp"
#include "core/errors.hpp"
#include "sweep/sweep_values.hpp"

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

namespace {

[[noreturn]] void refuse(const std::filesystem::path& path, const std::string& field,
                         const std::string& expected, const nlohmann::json& got) {
  throw InputError(path.string() + ": " + field + ": expected " + expected + ", got " + got.dump() +
                   " (the sweep's manifest was edited or damaged)");
}

std::string text_field(const std::filesystem::path& path, const nlohmann::json& manifest,
                       const std::string& field) {
  const nlohmann::json value = manifest.contains(field) ? manifest[field] : nlohmann::json();
  if (!value.is_string()) refuse(path, field, "a text", value);
  return value.get<std::string>();
}

// Read through the world key it stands for (run.replicates, run.seed), so that the manifest
// obeys the rules the sweep file did: a negative or fractional count is refused, not wrapped
// or cut.
WorldSpec through_key(const std::filesystem::path& path, const nlohmann::json& manifest,
                      const std::string& field, const std::string& key_path) {
  const WorldKey& key = *find_world_key(key_path);
  const nlohmann::json value = manifest.contains(field) ? manifest[field] : nlohmann::json();
  WorldSpec world;
  try {
    if (!value.is_number()) throw KeyValueError(key.expected);
    key.read(world, YAML::Load(value.dump()));
  } catch (const KeyValueError& e) {
    refuse(path, field, e.expected, value);
  } catch (const YAML::Exception&) {
    refuse(path, field, key.expected, value);
  }
  return world;
}

// Each parameter a world key with one or more values, each key once.
std::vector<SweepParameter> parameters_of(const std::filesystem::path& path,
                                          const nlohmann::json& manifest) {
  const nlohmann::json list =
      manifest.contains("parameters") ? manifest["parameters"] : nlohmann::json();
  const std::string expected =
      "a list of {key, values}: a world key the sweep does not set itself and one or more texts";
  if (!list.is_array() || list.empty()) refuse(path, "parameters", expected, list);
  std::vector<SweepParameter> parameters;
  for (const nlohmann::json& p : list) {
    const bool texts = p.is_object() && p.contains("values") && p["values"].is_array() &&
                       !p["values"].empty() &&
                       std::all_of(p["values"].begin(), p["values"].end(),
                                   [](const nlohmann::json& v) { return v.is_string(); });
    if (!texts || !p.contains("key") || !p["key"].is_string() ||
        find_world_key(p["key"].get<std::string>()) == nullptr ||
        swept_by_sweep(p["key"].get<std::string>()))
      refuse(path, "parameters", expected, p);
    const std::string key = p["key"].get<std::string>();
    // A value is part of a run's folder name: as the sweep file's, a number or a name.
    for (const nlohmann::json& value : p["values"]) {
      if (!is_sweep_value_text(value.get<std::string>()))
        refuse(path, "parameters", "values of letters, digits, '.', '_', '+' and '-'", value);
    }
    const bool repeated = std::any_of(parameters.begin(), parameters.end(),
                                      [&](const SweepParameter& q) { return q.key == key; });
    if (repeated) refuse(path, "parameters", "each key once", p);
    parameters.push_back({key, p["values"].get<std::vector<std::string>>()});
  }
  return parameters;
}

}  // namespace

SweepPlan read_manifest(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / kManifestFile;
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(folder.string() + ": not a sweep output folder (no " + kManifestFile + ")");
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json manifest;
  try {
    manifest = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path.string() + ": not a valid sweep manifest: " + e.what());
  }
  if (!manifest.is_object())
    refuse(path, "the manifest", "an object of name, seed, replicates, parameters", manifest);
  SweepPlan plan;
  plan.source = path.string();
  plan.recorded = true;
  plan.name = text_field(path, manifest, "name");
  plan.seed = through_key(path, manifest, "seed", "run.seed").run.seed;
  plan.replicates = through_key(path, manifest, "replicates", "run.replicates").run.replicates;
  plan.base_world = text_field(path, manifest, "base_world");
  plan.parameters = parameters_of(path, manifest);
  return plan;
}

}  // namespace swarmagg
