#include "config/world_override.hpp"

#include "config/yaml_document.hpp"
#include "core/errors.hpp"

namespace swarmagg {

WorldOverride parse_override(const std::string& assignment) {
  const auto equals = assignment.find('=');
  const std::string at = "--set " + assignment;
  if (equals == std::string::npos || equals == 0) {
    throw InputError(at + ": expected key.path=value, e.g. --set robots.count=80");
  }
  WorldOverride result{assignment.substr(0, equals), YAML::Node(), "--set"};
  // Messages name the key and the line and column within the value, not the whole
  // assignment: a long value would bury them.
  result.value = parse_one_yaml_document(assignment.substr(equals + 1), "--set " + result.key,
                                         "a --set value");
  return result;
}

std::vector<WorldOverride> parse_overrides(const std::vector<std::string>& assignments) {
  std::vector<WorldOverride> result;
  result.reserve(assignments.size());
  for (const std::string& a : assignments) result.push_back(parse_override(a));
  return result;
}

void refuse_repeated_keys(const std::vector<WorldOverride>& overrides) {
  for (std::size_t i = 0; i < overrides.size(); ++i) {
    for (std::size_t j = i + 1; j < overrides.size(); ++j) {
      if (overrides[i].key == overrides[j].key)
        throw InputError("--set " + overrides[i].key + " is given twice: give it once");
    }
  }
}

}  // namespace swarmagg
