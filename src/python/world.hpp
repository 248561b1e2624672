#pragma once
// swarmagg.World: a loaded, checked world (config/world_spec.hpp), immutable and shared by
// the runs and simulations made from it. Python arguments that stand for world keys
// (replicates, seed, threads, engine) are applied as overrides of those keys, exactly as the
// CLI's typed options are, so a call and the same command line run the same world.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/world_override.hpp"
#include "config/world_spec.hpp"
#include "python/bound_class.hpp"

namespace swarmagg::python {

struct World {
  using BoundToPython = void;

  std::shared_ptr<const WorldSpec> spec;
  // What load_world's `set` changed of the world file, "key=value" each, as summary.json's
  // `overrides` names the CLI's --set texts.
  std::vector<std::string> changes;
};

// A Python int as a YAML integer: any value from -2^63 to 2^64 - 1 (a seed may use all 64
// bits); InputError naming `name` beyond.
YAML::Node yaml_integer(pybind11::handle value, const std::string& name);

// The override of world key `key` by the Python argument `name`, when it was given.
template <typename T>
void add_argument(std::vector<WorldOverride>& overrides, const char* key,
                  const std::optional<T>& value, const char* name) {
  if (value) overrides.push_back(typed_override(key, *value, name));
}
// A Python integer argument (an int, or any integer with __index__ such as numpy's; a bool
// or a float is a TypeError) as a YAML integer, by yaml_integer.
YAML::Node yaml_index(pybind11::handle value, const std::string& name);

inline void add_argument(std::vector<WorldOverride>& overrides, const char* key,
                         const std::optional<pybind11::object>& value, const char* name) {
  if (value) overrides.emplace_back(key, yaml_index(*value, name), name);
}

// `world` with `overrides` applied and checked again; InputError (ValueError) when a value
// does not fit its key. Its `changes` gain the overrides, as summary.json names the CLI's
// --engine, --replicates and --seed (not --threads); a key changed before names its new value.
World with_overrides(const World& world, const std::vector<WorldOverride>& overrides);

}  // namespace swarmagg::python
