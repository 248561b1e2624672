#pragma once
// A world key set from outside the world file: `--set key.path=value`, whose value is read
// as YAML, or a typed command-line option, whose value becomes the key's value as it is and
// is never re-read as YAML text (a folder name holding `"` or `\` stays that name).
#include <yaml-cpp/yaml.h>

#include <string>
#include <utility>
#include <vector>

namespace swarmagg {

struct WorldOverride {
  // Explicit, so that a braced list of `--set` texts never reads as one override.
  explicit WorldOverride(std::string key_path, YAML::Node key_value, std::string given_by)
      : key(std::move(key_path)), value(std::move(key_value)), origin(std::move(given_by)) {}

  std::string key;     // a world key path, e.g. "render.dir"
  YAML::Node value;    // a scalar (or a list, from --set)
  std::string origin;  // names it in messages: "--set", "--render-dir"
  // Set for a sweep over controller types: a controller.* key that one swept type reads is
  // given to every point, so the types that ignore it do not refuse it.
  bool any_controller = false;
};

// `key.path=value` as `--set` takes it; throws InputError when there is no `=` or the value
// is not YAML.
WorldOverride parse_override(const std::string& assignment);
std::vector<WorldOverride> parse_overrides(const std::vector<std::string>& assignments);

// InputError when two --set give one key: the last would win and the first be silently
// unused (as an option and a --set of its key would be).
void refuse_repeated_keys(const std::vector<WorldOverride>& overrides);

// A typed value (number, string) for `key`; `origin` is the option that gave it.
template <typename T>
WorldOverride typed_override(std::string key, const T& value, std::string origin) {
  return WorldOverride(std::move(key), YAML::Node(value), std::move(origin));
}

}  // namespace swarmagg
