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
  try {
    result.value = parse_one_yaml_document(assignment.substr(equals + 1), "value", "a --set value");
  } catch (const InputError& e) {
    // The assignment is cut short: a long value would bury the message.
    constexpr std::size_t kShown = 80;
    const std::string shown =
        assignment.size() <= kShown ? assignment : assignment.substr(0, kShown) + "...";
    throw InputError("--set " + shown + ": the value is not valid YAML: " + e.what());
  }
  return result;
}

std::vector<WorldOverride> parse_overrides(const std::vector<std::string>& assignments) {
  std::vector<WorldOverride> result;
  result.reserve(assignments.size());
  for (const std::string& a : assignments) result.push_back(parse_override(a));
  return result;
}

}  // namespace swarmagg
