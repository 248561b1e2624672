#include "sweep/sweep_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "config/did_you_mean.hpp"
#include "config/input_file.hpp"
#include "config/world_keys.hpp"
#include "config/world_loader.hpp"
#include "config/world_writer.hpp"
#include "config/yaml_document.hpp"
#include "core/errors.hpp"
#include "sweep/sweep_values.hpp"

namespace swarmagg {
namespace {

const std::vector<std::string> kSweepKeys = {"name", "base", "parameters", "replicates", "seed"};

std::string where(const std::string& source, const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return source;
  return source + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string shown(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

[[noreturn]] void unknown(const std::string& at, const std::string& what, const std::string& name,
                          const std::vector<std::string>& known) {
  std::string message = at + ": unknown " + what + " '" + name + "'";
  if (auto suggestion = closest_name(name, known))
    message += " (did you mean '" + *suggestion + "'?)";
  throw InputError(message);
}

// Reads `node` into `world` through the world key `path`, so sweep values obey exactly the
// rules of world files and `--set`.
void read_through_key(WorldSpec& world, const std::string& path, const YAML::Node& node,
                      const std::string& at, const std::string& label) {
  const WorldKey& key = *find_world_key(path);
  try {
    key.read(world, node);
  } catch (const KeyValueError& e) {
    throw InputError(at + ": " + label + ": expected " + e.expected + ", got " + shown(node));
  } catch (const YAML::Exception&) {
    throw InputError(at + ": " + label + ": expected " + key.expected + ", got " + shown(node));
  }
}

class SweepReader {
 public:
  explicit SweepReader(std::string source) : source_(std::move(source)) {}

  SweepPlan read(const YAML::Node& document) {
    if (!document.IsMap()) {
      throw InputError(where(source_, document) + ": expected a sweep (a mapping with base:, " +
                       "parameters:, replicates:, seed:), got " + shown(document));
    }
    index_entries(document);
    const WorldSpec base = read_base();
    SweepPlan plan;
    plan.source = source_;
    plan.name = read_name();
    plan.replicates = read_run_key("replicates", "run.replicates", base).run.replicates;
    plan.seed = read_run_key("seed", "run.seed", base).run.seed;
    plan.parameters = read_parameters(base);
    plan.base_world = world_to_yaml(run_base(base));
    return plan;
  }

 private:
  void index_entries(const YAML::Node& document) {
    for (const auto& entry : document) {
      const std::string at = where(source_, entry.first);
      if (!entry.first.IsScalar()) throw InputError(at + ": a key must be a plain name");
      const std::string& key = entry.first.Scalar();
      if (std::find(kSweepKeys.begin(), kSweepKeys.end(), key) == kSweepKeys.end()) {
        unknown(at, "sweep key", key, kSweepKeys);
      }
      if (!entries_.emplace(key, entry.second).second)
        throw InputError(at + ": '" + key + "' given twice");
    }
  }

  const YAML::Node* value_of(const std::string& key) const {
    const auto found = entries_.find(key);
    return found == entries_.end() ? nullptr : &found->second;
  }

  const YAML::Node& required(const std::string& key, const std::string& example) const {
    const YAML::Node* node = value_of(key);
    if (node == nullptr) throw InputError(source_ + ": missing '" + key + ":' (" + example + ")");
    return *node;
  }

  WorldSpec read_base() const {
    const YAML::Node& node = required("base",
                                      "the world file the sweep varies, e.g. "
                                      "base: ../worlds/examples/demo.yaml");
    const std::string at = where(source_, node);
    if (!node.IsScalar() || node.Scalar().empty()) {
      throw InputError(at + ": base: expected the path of a world file, got " + shown(node));
    }
    std::filesystem::path path(node.Scalar());
    if (path.is_relative()) path = std::filesystem::path(source_).parent_path() / path;
    try {
      return load_world(path.lexically_normal().string());
    } catch (const InputError& e) {
      throw InputError(at + ": base: " + e.what());
    }
  }

  std::string read_name() const {
    WorldSpec scratch;
    if (const YAML::Node* node = value_of("name")) {
      read_through_key(scratch, "name", *node, where(source_, *node), "name");
      return scratch.name;
    }
    const std::string stem = std::filesystem::path(source_).stem().string();
    read_through_key(scratch, "name", YAML::Node(stem), source_,
                     "the file name (give the sweep a name: instead)");
    return scratch.name;
  }

  WorldSpec read_run_key(const std::string& key, const std::string& path, WorldSpec base) const {
    if (const YAML::Node* node = value_of(key))
      read_through_key(base, path, *node, where(source_, *node), key);
    return base;
  }

  std::vector<SweepParameter> read_parameters(const WorldSpec& base) const {
    const YAML::Node& node = required("parameters",
                                      "world key paths with lists of values, e.g. "
                                      "parameters: {robots.count: [50, 100]}");
    const std::string at = where(source_, node);
    if (!node.IsMap() || node.size() == 0) {
      throw InputError(at + ": parameters: expected a mapping of world key paths to lists of " +
                       "values, e.g. {robots.count: [50, 100]}, got " +
                       (node.IsMap() ? std::string("an empty mapping") : shown(node)));
    }
    std::vector<SweepParameter> parameters;
    for (const auto& entry : node) {
      for (const SweepParameter& earlier : parameters) {
        if (entry.first.IsScalar() && entry.first.Scalar() == earlier.key) {
          throw InputError(where(source_, entry.first) + ": parameters: '" + earlier.key +
                           "' given twice");
        }
      }
      parameters.push_back(read_parameter(entry.first, entry.second, base));
    }
    return parameters;
  }

  SweepParameter read_parameter(const YAML::Node& key_node, const YAML::Node& list,
                                const WorldSpec& base) const {
    const std::string at = where(source_, key_node);
    if (!key_node.IsScalar()) throw InputError(at + ": parameters: a key must be a world key path");
    SweepParameter parameter{key_node.Scalar(), {}};
    const std::string label = "parameters: " + parameter.key;
    if (find_world_key(parameter.key) == nullptr) {
      unknown(at + ": parameters", "world key", parameter.key, world_key_paths());
    }
    if (swept_by_sweep(parameter.key)) {
      throw InputError(at + ": " + label + ": cannot be swept; the sweep sets it (use the " +
                       "sweep's replicates: and seed:; sweeps write no frames)");
    }
    if (!list.IsSequence() || list.size() == 0) {
      const std::string got = list.IsSequence() ? "an empty list" : shown(list);
      throw InputError(where(source_, list) + ": " + label +
                       ": expected a non-empty list of values, e.g. [50, 100], got " + got);
    }
    for (const YAML::Node& value : list) {
      add_value(parameter, value, base, label);
    }
    return parameter;
  }

  // Stores the value as the resolved world would write it, so "1e-3" and "0.001" are the
  // same point (same folder, same seed).
  void add_value(SweepParameter& parameter, const YAML::Node& value, WorldSpec world,
                 const std::string& label) const {
    const std::string at = where(source_, value);
    read_through_key(world, parameter.key, value, at, label);
    const YAML::Node written = find_world_key(parameter.key)->write(world);
    const std::string text = written.IsScalar() ? written.Scalar() : "";
    if (!is_sweep_value_text(text)) {
      throw InputError(at + ": " + label + ": sweep values must be numbers or names " +
                       "(letters, digits, '.', '_', '+', '-'), got " + shown(value));
    }
    if (std::find(parameter.values.begin(), parameter.values.end(), text) !=
        parameter.values.end()) {
      throw InputError(at + ": " + label + ": the value " + shown(value) + " (read as " + text +
                       ") is listed twice");
    }
    parameter.values.push_back(text);
  }

  // The base every run starts from: one replicate (a run is one replicate) and no frames.
  static WorldSpec run_base(WorldSpec base) {
    base.run.replicates = 1;
    base.render.every = 0;
    return base;
  }

  std::string source_;
  std::map<std::string, YAML::Node> entries_;
};

YAML::Node parse(const std::string& path) {
  return parse_one_yaml_document(read_input_file(path, "sweep file"), path, "a sweep file");
}

}  // namespace

SweepPlan load_sweep(const std::string& path) {
  return SweepReader(path).read(parse(path));
}

}  // namespace swarmagg
