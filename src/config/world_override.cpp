#include "config/world_override.hpp"

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
    result.value = YAML::Load(assignment.substr(equals + 1));
  } catch (const YAML::ParserException& e) {
    throw InputError(at + ": the value is not valid YAML: " + e.msg);
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
