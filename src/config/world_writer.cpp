#include "config/world_writer.hpp"

#include <yaml-cpp/yaml.h>

#include "config/controller_catalog.hpp"
#include "config/world_keys.hpp"

namespace swarmagg {
namespace {

// Inserts `value` at the dotted `path` below `root`, creating the blocks on the way.
void insert(YAML::Node root, const std::string& path, const YAML::Node& value) {
  const auto dot = path.find('.');
  if (dot == std::string::npos) {
    root[path] = value;
    return;
  }
  const std::string head = path.substr(0, dot);
  if (!root[head]) root[head] = YAML::Node(YAML::NodeType::Map);
  insert(root[head], path.substr(dot + 1), value);
}

}  // namespace

std::string world_to_yaml(const WorldSpec& spec) {
  YAML::Node root(YAML::NodeType::Map);
  for (const WorldKey& key : world_keys()) {
    // Keys the world's controller does not read (another controller's) mean nothing to it.
    if (!controller_reads(spec, key)) continue;
    insert(root, key.path, key.write(spec));
  }
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

}  // namespace swarmagg
