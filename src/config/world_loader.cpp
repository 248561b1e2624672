#include "config/world_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

#include "config/did_you_mean.hpp"
#include "config/world_keys.hpp"
#include "core/errors.hpp"

namespace swarmagg {
namespace {

// Where a value came from, for messages: "file:line:column" or "--set".
std::string where(const std::string& source, const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return source;
  return source + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string shown_value(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

bool is_block(const std::string& path) {
  for (const std::string& b : world_blocks()) {
    if (b == path) return true;
  }
  return false;
}

[[noreturn]] void unknown_key(const std::string& at, const std::string& path) {
  std::string message = at + ": unknown key '" + path + "'";
  if (auto suggestion = closest_name(path, world_key_paths())) {
    message += " (did you mean '" + *suggestion + "'?)";
  }
  throw InputError(message);
}

void apply_value(WorldSpec& spec, const WorldKey& key, const YAML::Node& value,
                 const std::string& at) {
  try {
    key.read(spec, value);
  } catch (const KeyValueError& e) {
    throw InputError(at + ": " + key.path + ": expected " + e.expected + ", got " +
                     shown_value(value));
  } catch (const YAML::Exception& e) {
    throw InputError(at + ": " + key.path + ": expected " + key.expected + ", got " +
                     shown_value(value));
  }
}

class DocumentReader {
 public:
  DocumentReader(WorldSpec& spec, std::string source) : spec_(spec), source_(std::move(source)) {}

  void read_block(const YAML::Node& map, const std::string& prefix) {
    for (const auto& entry : map) {
      const std::string at = where(source_, entry.first);
      if (!entry.first.IsScalar()) throw InputError(at + ": a key must be a plain name");
      const std::string path = prefix.empty() ? entry.first.Scalar()
                                              : prefix + "." + entry.first.Scalar();
      if (!seen_.insert(path).second) throw InputError(at + ": key '" + path + "' given twice");
      read_entry(path, entry.second, at);
    }
  }

  const std::set<std::string>& seen() const { return seen_; }

 private:
  void read_entry(const std::string& path, const YAML::Node& value, const std::string& at) {
    if (is_block(path)) {
      if (!value.IsMap()) {
        throw InputError(at + ": " + path + ": expected a mapping of keys, got " +
                         shown_value(value));
      }
      read_block(value, path);
      return;
    }
    const WorldKey* key = find_world_key(path);
    if (key == nullptr) unknown_key(at, path);
    apply_value(spec_, *key, value, where(source_, value));
  }

  WorldSpec& spec_;
  std::string source_;
  std::set<std::string> seen_;
};

YAML::Node parse_yaml(const std::string& text, const std::string& source) {
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(source + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": YAML syntax error: " + e.msg);
  }
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the world file (does it exist?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the world file");
  return text.str();
}

void check_placement(const WorldSpec& spec, bool count_given) {
  const auto& placed = spec.robots.placement;
  if (placed.empty()) return;
  if (count_given && static_cast<std::size_t>(spec.robots.count) != placed.size()) {
    throw InputError(spec.source + ": robots.placement: lists " + std::to_string(placed.size()) +
                     " agents but robots.count is " + std::to_string(spec.robots.count));
  }
  const double r = spec.robots.radius;
  const bool walls = spec.arena.topology == Topology::Walls;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const double margin = walls ? r : 0.0;
    const bool inside = placed[i].x >= margin && placed[i].x <= spec.arena.width - margin &&
                        placed[i].y >= margin && placed[i].y <= spec.arena.height - margin;
    if (!inside) {
      throw InputError(spec.source + ": robots.placement: agent " + std::to_string(i) +
                       " at (" + format_number(placed[i].x) + ", " + format_number(placed[i].y) +
                       ") is outside the " + format_number(spec.arena.width) + " x " +
                       format_number(spec.arena.height) + " arena");
    }
  }
}

WorldSpec load_document(const YAML::Node& document, const std::string& source,
                        const std::vector<std::string>& overrides) {
  if (!document.IsDefined() || document.IsNull()) {
    throw InputError(source + ": the world file is empty; expected a mapping of world keys "
                              "(for example 'robots: {count: 50}')");
  }
  if (!document.IsMap()) {
    throw InputError(where(source, document) + ": expected a mapping of world keys, got " +
                     shown_value(document));
  }
  WorldSpec spec;
  spec.source = source;
  DocumentReader reader(spec, source);
  reader.read_block(document, "");
  bool count_given = reader.seen().count("robots.count") > 0;
  for (const std::string& assignment : overrides) {
    count_given = count_given || assignment.rfind("robots.count=", 0) == 0;
    apply_override(spec, assignment);
  }
  if (!count_given && !spec.robots.placement.empty()) {
    spec.robots.count = static_cast<int>(spec.robots.placement.size());
  }
  check_placement(spec, count_given);
  check_world(spec);
  return spec;
}

[[noreturn]] void impossible(const WorldSpec& spec, const std::string& key,
                             const std::string& why) {
  throw InputError(spec.source + ": " + key + ": " + why);
}

}  // namespace

void apply_override(WorldSpec& spec, const std::string& assignment) {
  const auto equals = assignment.find('=');
  const std::string at = "--set " + assignment;
  if (equals == std::string::npos || equals == 0) {
    throw InputError(at + ": expected key.path=value, e.g. --set robots.count=80");
  }
  const std::string path = assignment.substr(0, equals);
  const WorldKey* key = find_world_key(path);
  if (key == nullptr) unknown_key("--set", path);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(equals + 1));
  } catch (const YAML::ParserException& e) {
    throw InputError(at + ": the value is not valid YAML: " + e.msg);
  }
  apply_value(spec, *key, value, "--set");
}

void check_world(const WorldSpec& spec) {
  const auto& robots = spec.robots;
  const double s = robots.detection_radius;
  if (s < 2.0 * robots.radius) {
    impossible(spec, "robots.detection_radius",
               "must be at least twice robots.radius (s = " + format_number(s) +
                   " < 2r = " + format_number(2.0 * robots.radius) + ")");
  }
  const double min_side = std::min(spec.arena.width, spec.arena.height);
  if (min_side < 2.0 * spec.sensing_radius() + 2.0 * robots.radius) {
    impossible(spec, "arena.width",
               "the arena (" + format_number(spec.arena.width) + " x " +
                   format_number(spec.arena.height) +
                   ") must be wider than twice the sensing radius plus a body");
  }
  // Random sequential placement jams near 55% coverage; beyond half the arena it fails.
  const double coverage = robots.count * 3.141592653589793 * robots.radius * robots.radius /
                          spec.arena.area();
  if (coverage > 0.5) {
    impossible(spec, "robots.count",
               std::to_string(robots.count) + " agents of radius " +
                   format_number(robots.radius) + " cover " +
                   format_number(std::round(coverage * 100.0)) +
                   "% of the arena; at most 50% can be placed without overlap");
  }
  if (spec.controller.type == ControllerType::Soysal && spec.controller.approach_radius <= s) {
    impossible(spec, "controller.approach_radius",
               "must exceed robots.detection_radius (" + format_number(s) + ")");
  }
  if (spec.steps() < 1) {
    impossible(spec, "run.duration", "is shorter than one step of engine.dt");
  }
  if (spec.steps() > 1'000'000'000'000LL) {
    impossible(spec, "run.duration", "needs more than 10^12 steps of engine.dt");
  }
  if (robots.speed * spec.engine.dt > 0.25 * min_side) {
    impossible(spec, "robots.speed", "moves an agent more than a quarter of the arena per step");
  }
  if (spec.render.replicate >= spec.run.replicates && spec.render.every > 0) {
    impossible(spec, "render.replicate",
               "is " + std::to_string(spec.render.replicate) + " but the run has only " +
                   std::to_string(spec.run.replicates) + " replicates (numbered from 0)");
  }
}

WorldSpec load_world_text(const std::string& text, const std::string& source,
                          const std::vector<std::string>& overrides) {
  return load_document(parse_yaml(text, source), source, overrides);
}

WorldSpec load_world(const std::string& path, const std::vector<std::string>& overrides) {
  return load_world_text(read_file(path), path, overrides);
}

}  // namespace swarmagg
