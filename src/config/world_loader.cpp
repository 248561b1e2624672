#include "config/world_loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include "config/controller_catalog.hpp"
#include "config/did_you_mean.hpp"
#include "config/input_file.hpp"
#include "config/world_keys.hpp"
#include "config/world_override.hpp"
#include "config/yaml_document.hpp"
#include "core/errors.hpp"
#include "geometry/pair_finder.hpp"

namespace swarmagg {
namespace {

std::string where(const std::string& source, const YAML::Node& node) {
  return where_mark(source, node.Mark());
}

// Text quoted back from the input is cut short: a message stays readable however long the
// offending key or value is.
std::string shortened(const std::string& text) {
  constexpr std::size_t kShown = 80;
  return text.size() <= kShown ? text : text.substr(0, kShown) + "...";
}

std::string shown_value(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + shortened(node.Scalar()) + "'";
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
  // Nothing is a typo of an empty name: the nearest key would be a guess.
  if (path.empty()) throw InputError(at + ": an empty key; expected a key such as robots.count");
  std::string message = at + ": unknown key '" + shortened(path) + "'";
  // Edit distance costs time proportional to the name's length; a name far longer than any
  // key path is no typo of one (a 2 MB key took 13 s here).
  constexpr std::size_t kLongestTypo = 64;
  if (path.size() > kLongestTypo) throw InputError(message);
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
                     (e.got.empty() ? shown_value(value) : e.got));
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
      const std::string path =
          prefix.empty() ? entry.first.Scalar() : prefix + "." + entry.first.Scalar();
      if (!seen_.emplace(path, at).second) {
        throw InputError(at + ": key '" + path + "' given twice");
      }
      read_entry(path, entry.second, at);
    }
  }

  // Every key read, with where it stood.
  const std::map<std::string, std::string>& seen() const { return seen_; }

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
    // A missing value's mark is where the next token starts (the next line): its key names it.
    apply_value(spec_, *key, value, value.IsNull() ? at : where(source_, value));
  }

  WorldSpec& spec_;
  std::string source_;
  std::map<std::string, std::string> seen_;
};

// Bodies must not overlap at the start (docs/worlds.md), as random placement guarantees. The pair
// named is the first in id order, whatever order the pair finder meets them in.
void check_no_overlap(const WorldSpec& spec) {
  const auto& placed = spec.robots.placement;
  const double contact = 2.0 * spec.robots.radius;
  PairFinder bodies;
  bodies.reset(spec.arena.geometry(), contact, placed.size());
  for (const PlacedAgent& a : placed) bodies.add({a.x, a.y});
  struct Overlap {
    std::uint32_t i, j;
    double distance;
  };
  std::optional<Overlap> first;
  bodies.for_each_pair([&](std::uint32_t i, std::uint32_t j, Vec2 d) {
    const double distance = norm(d);
    if (distance >= contact) return;  // touching is allowed
    if (!first || std::pair(i, j) < std::pair(first->i, first->j)) first = Overlap{i, j, distance};
  });
  if (!first) return;
  throw InputError(spec.source + ": robots.placement: agents " + std::to_string(first->i) +
                   " and " + std::to_string(first->j) + " overlap: their centres are " +
                   format_number(first->distance) +
                   " apart, bodies need 2 robots.radius = " + format_number(contact));
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
      // Between walls a body must fit: a centre closer than r to a wall overlaps it.
      const std::string where = walls ? " does not fit in the " + format_number(spec.arena.width) +
                                            " x " + format_number(spec.arena.height) +
                                            " walled arena (its body, radius " + format_number(r) +
                                            ", must lie within the walls)"
                                      : " is outside the " + format_number(spec.arena.width) +
                                            " x " + format_number(spec.arena.height) + " arena";
      throw InputError(spec.source + ": robots.placement: agent " + std::to_string(i) + " at (" +
                       format_number(placed[i].x) + ", " + format_number(placed[i].y) + ")" +
                       where);
    }
  }
  check_no_overlap(spec);
}

// Whether controller type `entry` reads `path`: as one of its own keys (several controllers
// may register the same path) or as a shared controller.* key.
bool reads(const ControllerCatalogEntry& entry, const std::string& path) {
  const auto& own = entry.keys;
  const auto& shared = entry.shared_keys;
  return std::any_of(own.begin(), own.end(), [&](const WorldKey& k) { return k.path == path; }) ||
         std::find(shared.begin(), shared.end(), path) != shared.end();
}

// A model.* key that the model of `world` does not read.
bool unread_model_key(const WorldSpec& world, const std::string& path) {
  return path.starts_with("model.") && find_world_key(path) != nullptr && !model_reads(world, path);
}

// A world of `type` as far as the key table goes (a sweep asks about types before worlds).
WorldSpec world_of_type(const std::string& type) {
  WorldSpec world;
  world.controller.type = type;
  return world;
}

// Whether `world` has a macroscopic model (one that reads some model.* key).
bool has_model(const WorldSpec& world) {
  const std::vector<std::string> paths = world_key_paths();
  return std::any_of(paths.begin(), paths.end(), [&](const std::string& path) {
    return path.starts_with("model.") && model_reads(world, path);
  });
}

// A controller.* key (not the type itself) that `controller` does not read.
bool unread_controller_key(const ControllerCatalogEntry& controller, const std::string& path) {
  return path.starts_with("controller.") && path != "controller.type" &&
         find_world_key(path) != nullptr && !reads(controller, path);
}

// A key `controller`'s worlds ignore: one of another controller's, or one its model does not
// read.
bool unread_key(const ControllerCatalogEntry& controller, const std::string& path) {
  return unread_controller_key(controller, path) ||
         unread_model_key(world_of_type(controller.type), path);
}

// " (read by controller type 'a', 'b')", or nothing when no type reads `path`.
std::string readers_of(const std::string& path) {
  std::string types;
  for (const ControllerCatalogEntry& entry : controller_catalog()) {
    if (!unread_key(entry, path)) types += (types.empty() ? "'" : ", '") + entry.type + "'";
  }
  const std::string readers =
      path.starts_with("model.") ? "the models of controller type " : "controller type ";
  return types.empty() ? "" : " (read by " + readers + types + ")";
}

// A file switched to another controller type by an override (a sweep over controller types)
// may hold keys of the type it was written for.
bool sets_controller_type(const std::vector<WorldOverride>& overrides) {
  return std::any_of(overrides.begin(), overrides.end(),
                     [](const WorldOverride& o) { return o.key == "controller.type"; });
}

// A controller key the world file gives that its controller never reads would be dropped in
// silence (the resolved world writes only what acts on the run): a Soysal key left in a file
// switched to Bayindir, say. The overrides are checked too (check_overrides_read).
void check_controller_reads(const WorldSpec& spec, const std::map<std::string, std::string>& seen,
                            const std::vector<WorldOverride>& overrides) {
  check_overrides_read(spec, overrides);
  if (sets_controller_type(overrides)) return;
  const ControllerCatalogEntry& controller = catalog_entry(spec.controller.type);
  for (const auto& [path, at] : seen) {
    if (!unread_controller_key(controller, path)) continue;
    throw InputError(at + ": " + path + ": controller type '" + spec.controller.type +
                     "' does not read this key" + readers_of(path) +
                     "; remove it or change controller.type");
  }
}

// "--set arena.width=1, --engine (engine.type=box2d)": the overrides as given, but those no
// check across keys reads (--threads, --seed), for messages.
std::string overrides_text(const std::vector<WorldOverride>& overrides) {
  std::string text;
  for (const WorldOverride& o : overrides) {
    if (o.key == "run.threads" || o.key == "run.seed") continue;
    const std::string value = o.value.IsScalar() ? shortened(o.value.Scalar()) : "[...]";
    const std::string given = o.origin == "--set" ? "--set " + o.key + "=" + value
                                                  : o.origin + " (" + o.key + "=" + value + ")";
    text += (text.empty() ? "" : ", ") + given;
  }
  return text;
}

// The checks across keys. One that fails after overrides names them too: the file alone may
// hold a valid world (`--set arena.width=1` made the arena too small for the file's radius),
// and a check reads keys of several blocks (the arena's side against the sensing radius).
void check_with_overrides(WorldSpec& spec, bool count_given,
                          const std::vector<WorldOverride>& overrides) {
  try {
    check_placement(spec, count_given);
    check_world(spec);
  } catch (const InputError& e) {
    const std::string changed = overrides_text(overrides);
    if (changed.empty()) throw;
    throw InputError(std::string(e.what()) + " (the world as changed by " + changed + ")");
  }
}

WorldSpec load_document(const YAML::Node& document, const std::string& source,
                        const std::vector<WorldOverride>& overrides) {
  if (!document.IsDefined() || document.IsNull()) {
    throw InputError(source +
                     ": the world file is empty; expected a mapping of world keys "
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
  for (const WorldOverride& override : overrides) {
    count_given = count_given || override.key == "robots.count";
    apply_override(spec, override);
  }
  if (!count_given && !spec.robots.placement.empty()) {
    spec.robots.count = static_cast<int>(spec.robots.placement.size());
  }
  check_with_overrides(spec, count_given, overrides);
  check_controller_reads(spec, reader.seen(), overrides);
  return spec;
}

[[noreturn]] void impossible(const WorldSpec& spec, const std::string& key,
                             const std::string& why) {
  throw InputError(spec.source + ": " + key + ": " + why);
}

}  // namespace

void apply_override(WorldSpec& spec, const WorldOverride& override) {
  const WorldKey* key = find_world_key(override.key);
  if (key == nullptr && is_block(override.key)) {
    const std::vector<std::string>& paths = world_key_paths();
    const auto first = std::find_if(paths.begin(), paths.end(), [&](const std::string& path) {
      return path.starts_with(override.key + ".");
    });
    throw InputError(override.origin + ": '" + override.key +
                     "' is a block of keys: set one of them" +
                     (first == paths.end() ? "" : ", e.g. " + *first + "=..."));
  }
  if (key == nullptr) unknown_key(override.origin, override.key);
  apply_value(spec, *key, override.value, override.origin);
}

bool controller_type_reads(const std::string& type, const std::string& path) {
  return !unread_key(catalog_entry(type), path);
}

void check_overrides_read(const WorldSpec& spec, const std::vector<WorldOverride>& overrides) {
  const ControllerCatalogEntry& controller = catalog_entry(spec.controller.type);
  // Overrides that set the type already (a sweep over types: then none of them reads it).
  const std::string remedy = sets_controller_type(overrides)
                                 ? "; no controller type given reads it: remove it, or add a "
                                   "type that does"
                                 : "; remove it or set controller.type too";
  for (const WorldOverride& override : overrides) {
    const bool unread =
        unread_controller_key(controller, override.key) || unread_model_key(spec, override.key);
    if (override.any_controller || !unread) continue;
    const std::string type = "controller type '" + spec.controller.type + "' (" + spec.source + ")";
    const std::string ignored =
        !override.key.starts_with("model.") ? "the world's " + type + " does not read this key"
        : has_model(spec) ? "the model of the world's " + type + " does not read this key"
                          : "the world's " + type + " has no model";
    throw InputError(override.origin + ": " + override.key + ": " + ignored +
                     ", so the run would ignore it" + readers_of(override.key) + remedy);
  }
}

void check_world(const WorldSpec& spec) {
  const auto& robots = spec.robots;
  const double s = robots.detection_radius;
  if (s < 2.0 * robots.radius) {
    impossible(spec, "robots.detection_radius",
               "must be at least twice robots.radius (s = " + format_number(s) +
                   " < 2r = " + format_number(2.0 * robots.radius) + ")");
  }
  // Positions (double here, float in Box2D) lose the resolution contacts at 2r need when the
  // arena is this much larger than a body; grids sized by the arena would overflow too.
  const double longest = std::max(spec.arena.width, spec.arena.height);
  if (longest > 1e6 * robots.radius) {
    impossible(spec, spec.arena.width >= spec.arena.height ? "arena.width" : "arena.height",
               "the arena (" + format_number(spec.arena.width) + " x " +
                   format_number(spec.arena.height) + ") spans more than 10^6 body radii (" +
                   "robots.radius = " + format_number(robots.radius) + ")");
  }
  const double min_side = std::min(spec.arena.width, spec.arena.height);
  const double smallest_side = 2.0 * spec.sensing_radius() + 2.0 * robots.radius;
  if (min_side < smallest_side) {
    impossible(spec, spec.arena.width <= spec.arena.height ? "arena.width" : "arena.height",
               "the arena (" + format_number(spec.arena.width) + " x " +
                   format_number(spec.arena.height) + ") must be at least " +
                   format_number(smallest_side) +
                   " wide and high: twice the largest sensing radius the controller reads (" +
                   format_number(spec.sensing_radius()) + ") plus a body's diameter (" +
                   format_number(2.0 * robots.radius) + ")");
  }
  // Random sequential placement jams near 55% coverage; beyond half the arena it fails.
  const double coverage =
      robots.count * 3.141592653589793 * robots.radius * robots.radius / spec.arena.area();
  if (coverage > 0.5) {
    impossible(spec, "robots.count",
               std::to_string(robots.count) + " agents of radius " + format_number(robots.radius) +
                   " cover " + format_number(std::ceil(coverage * 1000.0) / 10.0) +
                   "% of the arena; at most 50% can be placed without overlap");
  }
  const ControllerCatalogEntry& controller = catalog_entry(spec.controller.type);
  if (controller.check) {
    if (const std::optional<KeyProblem> problem = controller.check(spec)) {
      impossible(spec, problem->key, problem->why);
    }
  }
  // Compaction pulls only members an agent perceives: a spacing at or beyond s would pull
  // every perceived member in and push none out, so the aggregate could never settle.
  if (spec.controller.compaction.enabled && spec.compaction_spacing() >= s) {
    impossible(spec, "controller.compaction.spacing",
               "is " + format_number(spec.compaction_spacing()) +
                   (spec.controller.compaction.spacing ? "" : " (2 robots.radius)") +
                   " but must be below robots.detection_radius (" + format_number(s) +
                   "); set it, or controller.compaction.enabled: false");
  }
  // Box2D's contact solver works with fixed tolerances in world units (a linear slop of
  // 0.005 u, b2_linearSlop): below this radius bodies may overlap by half their radius and
  // contacts do not hold (radius 1e-5 counted 433 encounters where the kinematic engine
  // counted 27). Above it the results still depend on the unit (docs/worlds.md).
  constexpr double kBox2dSmallestRadius = 0.01;
  if (spec.engine.type == EngineType::Box2D && robots.radius < kBox2dSmallestRadius) {
    impossible(spec, "robots.radius",
               "is " + format_number(robots.radius) + " but the Box2D engine needs at least " +
                   format_number(kBox2dSmallestRadius) +
                   " (its contact tolerance is 0.005 u); write the world's lengths in a smaller "
                   "unit, ideally one in which the radius is near 1");
  }
  // Box2D's solver always slides bodies along their contacts.
  if (spec.engine.type == EngineType::Box2D && spec.engine.contact == ContactResponse::Stop) {
    impossible(spec, "engine.contact",
               "is stop, which only the kinematic engine offers (Box2D's contacts slide)");
  }
  // Compared before rounding: steps() cannot represent a count beyond 2^63.
  if (spec.run.duration / spec.engine.dt > 1e12) {
    impossible(spec, "run.duration", "needs more than 10^12 steps of engine.dt");
  }
  if (spec.steps() < 1) {
    impossible(spec, "run.duration", "is shorter than one step of engine.dt");
  }
  const double longest_move = spec.arena.geometry().longest_move(spec.sensing_radius());
  if (robots.speed * spec.engine.dt > longest_move) {
    impossible(spec, "robots.speed",
               "moves an agent " + format_number(robots.speed * spec.engine.dt) +
                   " per step (robots.speed * engine.dt), more than " +
                   format_number(longest_move) +
                   (spec.arena.topology == Topology::Torus
                        ? ": a quarter of the arena's shorter side less half the sensing radius "
                          "(two agents moving apart could otherwise meet through the torus's far "
                          "side unseen)"
                        : ": a quarter of the arena's shorter side"));
  }
  if (robots.speed > 0.0 &&
      robots.speed * spec.engine.dt < spec.arena.geometry().position_resolution()) {
    impossible(spec, "robots.speed",
               "moves an agent less than 10^-12 of the arena per step (robots.speed * "
               "engine.dt = " +
                   format_number(robots.speed * spec.engine.dt) +
                   "); positions cannot resolve such moves");
  }
  if (spec.render.replicate >= spec.run.replicates && spec.render.every > 0) {
    impossible(spec, "render.replicate",
               "is " + std::to_string(spec.render.replicate) + " but the run has only " +
                   std::to_string(spec.run.replicates) + " replicates (numbered from 0)");
  }
}

WorldSpec load_world_text_with(const std::string& text, const std::string& source,
                               const std::vector<WorldOverride>& overrides) {
  return load_document(parse_one_yaml_document(text, source, "a world file"), source, overrides);
}

WorldSpec load_world_text(const std::string& text, const std::string& source,
                          const std::vector<std::string>& assignments) {
  return load_world_text_with(text, source, parse_overrides(assignments));
}

WorldSpec load_world_with(const std::string& path, const std::vector<WorldOverride>& overrides) {
  return load_world_text_with(read_input_file(path, "world file"), path, overrides);
}

WorldSpec load_world(const std::string& path, const std::vector<std::string>& assignments) {
  return load_world_with(path, parse_overrides(assignments));
}

}  // namespace swarmagg
