#include "config/world_difference.hpp"

#include <yaml-cpp/yaml.h>

#include <utility>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "core/errors.hpp"

namespace swarmagg {
namespace {

constexpr const char* kSystemSections[] = {"arena", "robots", "controller", "engine"};
constexpr std::size_t kDifferencesNamed = 3;

using FlatKeys = std::vector<std::pair<std::string, std::string>>;

// Every scalar (and every sequence, as its flow text) under `node`, by dotted key.
void flatten(const YAML::Node& node, const std::string& key, FlatKeys& keys) {
  if (node.IsMap()) {
    for (const auto& entry : node) flatten(entry.second, key + "." + entry.first.Scalar(), keys);
    return;
  }
  YAML::Emitter text;
  text.SetSeqFormat(YAML::Flow);
  text.SetMapFormat(YAML::Flow);
  text << node;
  keys.emplace_back(key, text.c_str());
}

// The run keys a model's errors against a run depend on, beside its length: its recorded
// steps and (for the noise floors, batches of run.replicates) its replicates.
constexpr const char* kMeasuredRunKeys[] = {"record_every", "replicates"};
constexpr const char* kRunLengthKey = "run.duration / engine.dt";

// A run's length as the steps it runs (WorldSpec::steps), not as text: durations of 100 and
// 100.01 at dt 0.1 are the same 1,000 steps. A length that is not numbers is compared as text.
void flatten_run_length(const YAML::Node& world, FlatKeys& keys) {
  const YAML::Node duration = world["run"]["duration"];
  if (!duration) return;
  try {
    WorldSpec spec;
    spec.run.duration = duration.as<double>();
    if (world["engine"] && world["engine"]["dt"])
      spec.engine.dt = world["engine"]["dt"].as<double>();
    keys.emplace_back(kRunLengthKey, std::to_string(spec.steps()) + " steps");
  } catch (const YAML::Exception&) {
    flatten(duration, "run.duration", keys);
  }
}

FlatKeys system_keys(const YAML::Node& world, bool with_run) {
  FlatKeys keys;
  for (const char* section : kSystemSections) {
    if (world[section]) flatten(world[section], section, keys);
  }
  if (!with_run || !world["run"]) return keys;
  flatten_run_length(world, keys);
  for (const char* name : kMeasuredRunKeys) {
    if (world["run"][name]) flatten(world["run"][name], std::string("run.") + name, keys);
  }
  return keys;
}

const std::string* value_of(const FlatKeys& keys, const std::string& key) {
  for (const auto& [name, value] : keys) {
    if (name == key) return &value;
  }
  return nullptr;
}

// The text as this version writes it: read as a world, so that keys an older version did not
// write get their defaults and numbers one spelling. A text this version cannot load (a key
// it does not know) is compared as it stands.
std::string as_written_here(const std::string& text) {
  try {
    return world_to_yaml(load_world_text(text, "the earlier world"));
  } catch (const InputError&) {
    return text;
  }
}

// Keys that change nothing in the world: the Box2D settings of two kinematic worlds.
bool inert(const std::string& key, const FlatKeys& a, const FlatKeys& b) {
  const auto kinematic = [](const FlatKeys& keys) {
    const std::string* type = value_of(keys, "engine.type");
    return type && *type == "kinematic";
  };
  return key.starts_with("engine.box2d.") && kinematic(a) && kinematic(b);
}

std::vector<std::string> differences_of(const std::string& there, const WorldSpec& here,
                                        bool with_run) {
  FlatKeys theirs;
  try {
    theirs = system_keys(YAML::Load(as_written_here(there)), with_run);
  } catch (const YAML::Exception&) {
    theirs.clear();
  }
  if (theirs.empty()) return {"the world text: unreadable"};
  const FlatKeys ours = system_keys(YAML::Load(world_to_yaml(here)), with_run);
  std::vector<std::string> differences;
  for (const auto& [key, value] : ours) {
    const std::string* other = value_of(theirs, key);
    const std::string there_text = other ? *other : "none";
    if (there_text != value && !inert(key, ours, theirs))
      differences.push_back(key + ": " + there_text + " there, " + value + " here");
  }
  for (const auto& [key, value] : theirs) {
    if (!value_of(ours, key)) differences.push_back(key + ": " + value + " there, none here");
  }
  return differences;
}

}  // namespace

std::vector<std::string> system_differences(const std::string& there, const WorldSpec& here) {
  return differences_of(there, here, false);
}

std::vector<std::string> measured_run_differences(const std::string& there, const WorldSpec& here) {
  return differences_of(there, here, true);
}

std::vector<std::string> changed_keys(const WorldSpec& original, const WorldSpec& changed) {
  const auto all_keys = [](const WorldSpec& world) {
    FlatKeys keys;
    for (const auto& section : YAML::Load(world_to_yaml(world))) {
      if (section.first.Scalar() != "name") flatten(section.second, section.first.Scalar(), keys);
    }
    return keys;
  };
  const FlatKeys before = all_keys(original);
  std::vector<std::string> changes;
  for (const auto& [key, value] : all_keys(changed)) {
    const std::string* earlier = value_of(before, key);
    if (!earlier || *earlier != value) changes.push_back(key + "=" + value);
  }
  return changes;
}

std::string differences_text(const std::vector<std::string>& differences) {
  std::string text;
  for (std::size_t i = 0; i < differences.size() && i < kDifferencesNamed; ++i)
    text += (i ? "; " : "") + differences[i];
  if (differences.size() > kDifferencesNamed)
    text += "; and " + std::to_string(differences.size() - kDifferencesNamed) + " more";
  return text;
}

}  // namespace swarmagg
