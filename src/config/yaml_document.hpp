#pragma once
// YAML texts the user writes (world and sweep files, --set values) are one YAML document each:
// yaml-cpp's Load would silently drop a second one. Syntax errors name where they are.
#include <yaml-cpp/yaml.h>

#include <string>

namespace swarmagg {

// "file:line:column", or `source` alone for a value with no place (a --set's).
std::string where_mark(const std::string& source, const YAML::Mark& mark);

std::string syntax_error(const std::string& source, const YAML::Mark& mark,
                         const std::string& what);

// The one document of `text`; InputError naming `source` and where, when the text is not valid
// YAML, is nested too deep, or holds a second document that is not empty. `what` names the
// kind of text in that message: "a world file", "a sweep file".
YAML::Node parse_one_yaml_document(const std::string& text, const std::string& source,
                                   const std::string& what);

}  // namespace swarmagg
