#pragma once
// The registry of world-file keys (docs/reference/world-keys.md is printed from it by
// `swarmagg keys --markdown`): every dotted key path, its type, what it expects, what it
// means, how to read it into a WorldSpec and how to write it back. The loader, `--set`,
// `validate`, the resolved-world writer and the reference page all go through this one table.
#include <yaml-cpp/yaml.h>

#include <functional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

// Thrown by a key's reader when a value does not fit; the loader adds file, line and key.
struct KeyValueError {
  std::string expected;
};

struct WorldKey {
  std::string path;      // e.g. "robots.count"
  std::string type;      // e.g. "integer"
  std::string expected;  // e.g. "a whole number >= 1"
  std::function<void(WorldSpec&, const YAML::Node&)> read;
  std::function<YAML::Node(const WorldSpec&)> write;
  // Non-empty for a registered controller's own key: written back only for its worlds.
  std::string controller;
  std::vector<double> list_defaults;  // number_list_key's defaults
  std::string meaning;                // one line for the reference: what the key sets, units
};

// `key` with its meaning, as the reference page prints it.
WorldKey described(WorldKey key, std::string meaning);

const std::vector<WorldKey>& world_keys();
const WorldKey* find_world_key(const std::string& path);
// Blocks that hold keys ("arena", "engine", "engine.box2d", ...), in writing order.
const std::vector<std::string>& world_blocks();
std::vector<std::string> world_key_paths();

// A registered controller's key holding a list of numbers (ControllerSpec::parameters), each
// in [low, high], at least one; `defaults` when the world does not name it.
WorldKey number_list_key(std::string path, std::vector<double> defaults, double low, double high,
                         std::string controller);
// The values of such a key in `spec`, or its defaults.
const std::vector<double>& number_list(const WorldSpec& spec, const WorldKey& key);

// Shortest decimal text that reads back to the same double.
std::string format_number(double value);

}  // namespace swarmagg
