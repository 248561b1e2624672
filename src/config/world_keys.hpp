#pragma once
// The registry of world-file keys (docs/reference/world-keys.md is printed from it by
// `swarmagg keys --markdown`): every dotted key path, its type, what it expects, what it
// means, how to read it into a WorldSpec and how to write it back. The loader, `--set`,
// `validate`, the resolved-world writer and the reference page all go through this one table.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "config/world_spec.hpp"

// Declared, not included: this header reaches most of the code base through the controller
// catalog, and yaml-cpp's headers are among the slowest to compile; only the files that read
// or write nodes include <yaml-cpp/yaml.h>.
namespace YAML {
class Node;
}

namespace swarmagg {

// Thrown by a key's reader when a value does not fit; the loader adds file, line and key.
// `got` says what was wrong where the value as shown would not (one item of a list); empty,
// the loader shows the value.
struct KeyValueError {
  explicit KeyValueError(std::string expected_value, std::string instead = {})
      : expected(std::move(expected_value)), got(std::move(instead)) {}
  std::string expected;
  std::string got;
};

struct WorldKey {
  std::string path;      // e.g. "robots.count"
  std::string type;      // e.g. "integer"
  std::string expected;  // e.g. "a whole number >= 1"
  std::function<void(WorldSpec&, const YAML::Node&)> read;
  std::function<YAML::Node(const WorldSpec&)> write;
  // Non-empty for a registered controller's own key: written back only for its worlds.
  std::string controller;
  ControllerValue default_value;  // a controller key's value when the world does not name it
  std::string meaning;            // one line for the reference: what the key sets, units
};

// `key` with its meaning, as the reference page prints it.
WorldKey described(WorldKey key, std::string meaning);

const std::vector<WorldKey>& world_keys();
const WorldKey* find_world_key(const std::string& path);
// Blocks that hold keys ("arena", "engine", "engine.box2d", ...), in writing order.
const std::vector<std::string>& world_blocks();
std::vector<std::string> world_key_paths();

// A registered controller's own keys (ControllerSpec::parameters), built like the core keys
// and checked with the same messages: `path` is "controller.<name>", `fallback` the value
// when the world does not name it, `controller` the controller.type that reads it.
// A number in [low, high].
WorldKey number_key(std::string path, double fallback, double low, double high,
                    std::string controller);
// A whole number in [low, high].
WorldKey whole_number_key(std::string path, long long fallback, long long low, long long high,
                          std::string controller);
// A probability, in [0, 1].
WorldKey probability_key(std::string path, double fallback, std::string controller);
// One of `names`.
WorldKey name_choice_key(std::string path, std::string fallback, std::vector<std::string> names,
                         std::string controller);
// true or false.
WorldKey flag_key(std::string path, bool fallback, std::string controller);
// A list of one or more numbers, each in [low, high] (only where a list is meant, e.g. a
// value per number of neighbours).
WorldKey number_list_key(std::string path, std::vector<double> fallback, double low, double high,
                         std::string controller);

// The value of such a key in `spec`, or its fallback; the reader must match the builder.
double number(const WorldSpec& spec, const WorldKey& key);  // number_key, probability_key
long long whole_number(const WorldSpec& spec, const WorldKey& key);
const std::string& name_choice(const WorldSpec& spec, const WorldKey& key);
bool flag(const WorldSpec& spec, const WorldKey& key);
const std::vector<double>& number_list(const WorldSpec& spec, const WorldKey& key);

// Shortest decimal text that reads back to the same double.
std::string format_number(double value);

}  // namespace swarmagg
