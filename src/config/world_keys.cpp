#include "config/world_keys.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>

#include "config/controller_catalog.hpp"

namespace swarmagg {
namespace {

template <typename T>
using Access = std::function<T&(WorldSpec&)>;

std::string scalar_text(const YAML::Node& node, const std::string& expected) {
  if (!node.IsScalar()) throw KeyValueError{expected};
  return node.Scalar();
}

// An item of a list as a message shows it: a scalar quoted, a short list in flow style.
std::string shown_item(const YAML::Node& item) {
  if (item.IsScalar()) return "'" + item.Scalar() + "'";
  if (item.IsSequence()) {
    YAML::Emitter flow;
    flow.SetSeqFormat(YAML::Flow);
    flow << item;
    constexpr std::size_t kLongest = 40;
    return flow.good() && flow.size() <= kLongest ? std::string(flow.c_str()) : "a list";
  }
  return item.IsMap() ? "a mapping" : "empty";
}

double read_real(const YAML::Node& node, const std::string& expected) {
  const std::string text = scalar_text(node, expected);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    throw KeyValueError{expected};
  }
  return value;
}

long long read_integer(const YAML::Node& node, const std::string& expected) {
  const std::string text = scalar_text(node, expected);
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) throw KeyValueError{expected};
  return value;
}

struct RealBounds {
  double low;
  bool low_inclusive;
  double high;
  std::string expected;
};

const RealBounds kPositive{0.0, false, std::numeric_limits<double>::infinity(),
                           "a positive number"};
const RealBounds kNonNegative{0.0, true, std::numeric_limits<double>::infinity(), "a number >= 0"};
const RealBounds kProbability{0.0, true, 1.0, "a probability between 0 and 1"};
// Lengths (u) and speeds (u per tu) are computed with their squares and products (event
// times solve quadratics in them): within these bounds every such term stays a normal double,
// and the kinematic engine gives the same run, bit for bit, at any power-of-two scale of every
// length (tested). Far outside, squares overflow or vanish and the physics silently breaks.
const RealBounds kLength{1e-30, true, 1e30, "a length from 1e-30 to 1e30"};
const RealBounds kLengthOrZero{0.0, true, 1e30, "a number from 0 to 1e30"};
// Bounded like lengths, so that what is derived from it (3 leave timeouts) stays finite.
const RealBounds kTimeOrZero = kLengthOrZero;
// Box2D computes in float: a value beyond float's range becomes infinite there and fails
// Box2D's own checks (an abort), so it is refused here.
const RealBounds kBox2dNonNegative{0.0, true, 1e30, "a number from 0 to 1e30"};

double read_bounded_real(const YAML::Node& node, const RealBounds& bounds) {
  const double v = read_real(node, bounds.expected);
  const bool above = bounds.low_inclusive ? v >= bounds.low : v > bounds.low;
  if (!above || v > bounds.high) throw KeyValueError{bounds.expected};
  return v;
}

std::string whole_expected(long long low, long long high) {
  return "a whole number from " + std::to_string(low) + " to " + std::to_string(high);
}

long long read_whole(const YAML::Node& node, long long low, long long high,
                     const std::string& expected) {
  const long long v = read_integer(node, expected);
  if (v < low || v > high) throw KeyValueError{expected};
  return v;
}

const std::string kFlagExpected = "true or false";

bool read_flag(const YAML::Node& node) {
  const std::string text = scalar_text(node, kFlagExpected);
  if (text == "true") return true;
  if (text == "false") return false;
  throw KeyValueError{kFlagExpected};
}

std::string choice_expected(const std::vector<std::string>& names) {
  std::string expected = "one of:";
  for (std::size_t k = 0; k < names.size(); ++k) {
    expected += (k == 0 ? " " : ", ") + names[k];
  }
  return expected;
}

WorldKey real_key(std::string path, Access<double> access, const RealBounds& bounds) {
  auto read = [access, bounds](WorldSpec& w, const YAML::Node& node) {
    access(w) = read_bounded_real(node, bounds);
  };
  auto write = [access](const WorldSpec& w) {
    return YAML::Node(format_number(access(const_cast<WorldSpec&>(w))));
  };
  return {std::move(path), "number", bounds.expected, read, write, {}, {}, {}};
}

template <typename Int>
WorldKey integer_key(std::string path, Access<Int> access, long long low, long long high) {
  std::string expected = whole_expected(low, high);
  auto read = [access, low, high, expected](WorldSpec& w, const YAML::Node& node) {
    access(w) = static_cast<Int>(read_whole(node, low, high, expected));
  };
  auto write = [access](const WorldSpec& w) {
    return YAML::Node(std::to_string(access(const_cast<WorldSpec&>(w))));
  };
  return {std::move(path), "integer", expected, read, write, {}, {}, {}};
}

WorldKey seed_key(std::string path, Access<std::uint64_t> access) {
  std::string expected = "a whole number from 0 to 18446744073709551615";
  auto read = [access, expected](WorldSpec& w, const YAML::Node& node) {
    const std::string text = scalar_text(node, expected);
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) throw KeyValueError{expected};
    access(w) = value;
  };
  auto write = [access](const WorldSpec& w) {
    return YAML::Node(std::to_string(access(const_cast<WorldSpec&>(w))));
  };
  return {std::move(path), "integer", expected, read, write, {}, {}, {}};
}

WorldKey bool_key(std::string path, Access<bool> access) {
  auto read = [access](WorldSpec& w, const YAML::Node& node) { access(w) = read_flag(node); };
  auto write = [access](const WorldSpec& w) {
    return YAML::Node(access(const_cast<WorldSpec&>(w)) ? "true" : "false");
  };
  return {std::move(path), "boolean", kFlagExpected, read, write, {}, {}, {}};
}

template <typename Enum>
WorldKey enum_key(std::string path, Access<Enum> access,
                  std::vector<std::pair<std::string, Enum>> names) {
  std::vector<std::string> texts;
  for (const auto& name : names) texts.push_back(name.first);
  const std::string expected = choice_expected(texts);
  auto read = [access, names, expected](WorldSpec& w, const YAML::Node& node) {
    const std::string text = scalar_text(node, expected);
    for (const auto& [name, value] : names) {
      if (name == text) {
        access(w) = value;
        return;
      }
    }
    throw KeyValueError{expected};
  };
  auto write = [access, names](const WorldSpec& w) {
    const Enum value = access(const_cast<WorldSpec&>(w));
    for (const auto& [name, v] : names) {
      if (v == value) return YAML::Node(name);
    }
    return YAML::Node();
  };
  return {std::move(path), "choice", expected, read, write, {}, {}, {}};
}

// Whether `text` is well-formed UTF-8 (no overlong forms, surrogates or code points past
// U+10FFFF), as a YAML text must be.
bool is_utf8(std::string_view text) {
  std::size_t k = 0;
  while (k < text.size()) {
    const auto lead = static_cast<unsigned char>(text[k]);
    const int length = lead < 0x80   ? 1
                       : lead < 0xC2 ? 0
                       : lead < 0xE0 ? 2
                       : lead < 0xF0 ? 3
                       : lead < 0xF5 ? 4
                                     : 0;
    if (length == 0 || k + static_cast<std::size_t>(length) > text.size()) return false;
    std::uint32_t code = length == 1 ? lead : lead & (0x7Fu >> length);
    for (int i = 1; i < length; ++i) {
      const auto next = static_cast<unsigned char>(text[k + static_cast<std::size_t>(i)]);
      if ((next & 0xC0u) != 0x80u) return false;
      code = (code << 6) | (next & 0x3Fu);
    }
    const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
      return false;
    k += static_cast<std::size_t>(length);
  }
  return true;
}

WorldKey string_key(std::string path, Access<std::string> access) {
  const std::string expected = "a UTF-8 text without control characters";
  auto read = [access, expected](WorldSpec& w, const YAML::Node& node) {
    std::string text = scalar_text(node, expected);
    // A "\0" (possible in a quoted YAML string) would cut a path short where the C library
    // reads it: render.dir "a\0b" wrote frames into "a". Bytes that are not UTF-8 loaded, but
    // no JSON output (summary.json, rates.json) could hold them, nor Python's str.
    const bool control = std::any_of(text.begin(), text.end(),
                                     [](char c) { return static_cast<unsigned char>(c) < 0x20; });
    if (control || !is_utf8(text)) throw KeyValueError{expected};
    access(w) = std::move(text);
  };
  auto write = [access](const WorldSpec& w) {
    return YAML::Node(access(const_cast<WorldSpec&>(w)));
  };
  return {std::move(path), "text", expected, read, write, {}, {}, {}};
}

// A number whose default follows another key (written back resolved).
WorldKey optional_real_key(std::string path, Access<std::optional<double>> access,
                           std::function<double(const WorldSpec&)> resolved,
                           const RealBounds& bounds) {
  auto read = [access, bounds](WorldSpec& w, const YAML::Node& node) {
    access(w) = read_bounded_real(node, bounds);
  };
  auto write = [resolved](const WorldSpec& w) { return YAML::Node(format_number(resolved(w))); };
  return {std::move(path), "number", bounds.expected, read, write, {}, {}, {}};
}

WorldKey name_key() {
  const std::string expected =
      "a name of 1 to 128 letters, digits, '-', '_' or '.', not starting with '.'";
  auto read = [expected](WorldSpec& w, const YAML::Node& node) {
    const std::string text = scalar_text(node, expected);
    const bool ok = !text.empty() && text.size() <= 128 && text.front() != '.' &&
                    text.find_first_not_of(
                        "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                        "0123456789-_.") == std::string::npos;
    if (!ok) throw KeyValueError{expected};
    w.name = text;
  };
  auto write = [](const WorldSpec& w) { return YAML::Node(w.name); };
  return {"name", "text", expected, read, write, {}, {}, {}};
}

WorldKey placement_key() {
  const std::string expected = "'random' or a list of [x, y, heading_deg]";
  auto read = [expected](WorldSpec& w, const YAML::Node& node) {
    if (node.IsScalar() && node.Scalar() == "random") {
      w.robots.placement.clear();
      return;
    }
    if (!node.IsSequence()) throw KeyValueError{expected};
    if (node.size() == 0) throw KeyValueError{expected, "an empty list"};
    std::vector<PlacedAgent> placed;
    for (const YAML::Node& item : node) {
      // The agent at fault is named: "got a list" alone reads as if lists were refused.
      const auto wrong_agent = [&](const std::string& why) {
        return KeyValueError{expected, "a list whose item " + std::to_string(placed.size() + 1) +
                                           " (agent " + std::to_string(placed.size()) + ") is " +
                                           shown_item(item) + " (" + why + ")"};
      };
      if (!item.IsSequence() || item.size() != 3) throw wrong_agent("not 3 numbers");
      try {
        placed.push_back({read_real(item[0], expected), read_real(item[1], expected),
                          read_real(item[2], expected)});
      } catch (const KeyValueError&) {
        throw wrong_agent("not 3 finite numbers");
      }
    }
    w.robots.placement = std::move(placed);
  };
  auto write = [](const WorldSpec& w) {
    if (w.robots.placement.empty()) return YAML::Node("random");
    YAML::Node list(YAML::NodeType::Sequence);
    for (const PlacedAgent& a : w.robots.placement) {
      YAML::Node item(YAML::NodeType::Sequence);
      item.SetStyle(YAML::EmitterStyle::Flow);
      item.push_back(format_number(a.x));
      item.push_back(format_number(a.y));
      item.push_back(format_number(a.heading_deg));
      list.push_back(item);
    }
    return list;
  };
  return {"robots.placement", "placement", expected, read, write, {}, {}, {}};
}

// Any registered controller (controller_catalog.hpp), named in the message.
WorldKey controller_type_key() {
  std::string expected = "one of:";
  for (const ControllerCatalogEntry& entry : controller_catalog()) {
    expected += (expected.back() == ':' ? " " : ", ") + entry.type;
  }
  auto read = [expected](WorldSpec& w, const YAML::Node& node) {
    const std::string text = scalar_text(node, expected);
    for (const ControllerCatalogEntry& entry : controller_catalog()) {
      if (entry.type == text) {
        w.controller.type = text;
        return;
      }
    }
    throw KeyValueError{expected};
  };
  auto write = [](const WorldSpec& w) { return YAML::Node(w.controller.type); };
  return {"controller.type", "choice", expected, read, write, "", {}, {}};
}

std::vector<WorldKey> build_keys() {
  constexpr long long kMaxAgents = 100'000'000;
  constexpr long long kMaxInt = 1'000'000'000;
  std::vector<WorldKey> keys;
  keys.push_back(described(name_key(), "the world's name; the default run folder is runs/<name>/"));
  keys.push_back(
      described(real_key(
                    "arena.width", [](WorldSpec& w) -> double& { return w.arena.width; }, kLength),
                "arena width W, u"));
  keys.push_back(described(
      real_key(
          "arena.height", [](WorldSpec& w) -> double& { return w.arena.height; }, kLength),
      "arena height H, u"));
  keys.push_back(
      described(enum_key<Topology>("arena.topology",
                                   [](WorldSpec& w) -> Topology& { return w.arena.topology; },
                                   {{"torus", Topology::Torus}, {"walls", Topology::Walls}}),
                "torus: an agent leaving one side comes back on the other and every distance is "
                "the minimum-image one; walls: reflecting sides"));
  keys.push_back(described(
      integer_key<int>(
          "robots.count", [](WorldSpec& w) -> int& { return w.robots.count; }, 1, kMaxAgents),
      "number of agents N; without it, a placement list sets it"));
  keys.push_back(described(
      real_key(
          "robots.radius", [](WorldSpec& w) -> double& { return w.robots.radius; }, kLength),
      "body radius r, u"));
  keys.push_back(
      described(real_key(
                    "robots.detection_radius",
                    [](WorldSpec& w) -> double& { return w.robots.detection_radius; }, kLength),
                "detection radius s, centre to centre, u; at least 2 robots.radius"));
  keys.push_back(described(
      real_key(
          "robots.speed", [](WorldSpec& w) -> double& { return w.robots.speed; }, kLengthOrZero),
      "speed v, u per tu"));
  keys.push_back(
      described(placement_key(),
                "random: uniform positions without overlapping bodies, uniform headings; or one "
                "[x, y, heading] per agent, heading in degrees counter-clockwise from +x"));
  keys.push_back(
      described(controller_type_key(), "the controller every agent runs (docs/controllers.md)"));
  keys.push_back(
      described(real_key(
                    "controller.p_leave",
                    [](WorldSpec& w) -> double& { return w.controller.p_leave; }, kProbability),
                "bayindir: probability per step that a waiting agent starts to leave (p)"));
  keys.push_back(described(
      real_key(
          "controller.leave_timeout",
          [](WorldSpec& w) -> double& { return w.controller.leave_timeout; }, kTimeOrZero),
      "how long a LEAVE lasts before the agent searches again, tu"));
  keys.push_back(described(
      bool_key("controller.join", [](WorldSpec& w) -> bool& { return w.controller.join; }),
      "searchers may join aggregates; false: they stop only for other searchers (aggregates of "
      "two)"));
  keys.push_back(described(
      bool_key("controller.leave", [](WorldSpec& w) -> bool& { return w.controller.leave; }),
      "waiting agents may leave; false: nobody leaves"));
  keys.push_back(
      described(enum_key<IsolatedWait>(
                    "controller.isolated_wait",
                    [](WorldSpec& w) -> IsolatedWait& { return w.controller.isolated_wait; },
                    {{"resume", IsolatedWait::Resume}, {"stay", IsolatedWait::Stay}}),
                "a waiting agent that perceives no waiting agent any more: resume searching, or "
                "stay waiting alone"));
  keys.push_back(described(
      real_key(
          "controller.approach_radius",
          [](WorldSpec& w) -> double& { return w.controller.approach_radius; }, kLength),
      "soysal: approach radius s_a, u; a searcher moves towards the nearest agent within it"));
  keys.push_back(described(
      real_key(
          "controller.p0", [](WorldSpec& w) -> double& { return w.controller.p0; }, kProbability),
      "soysal: leave probability per step P_l before controller.leave_law divides it"));
  keys.push_back(
      described(enum_key<LeaveLaw>("controller.leave_law",
                                   [](WorldSpec& w) -> LeaveLaw& { return w.controller.leave_law; },
                                   {{"constant", LeaveLaw::Constant},
                                    {"inverse", LeaveLaw::Inverse},
                                    {"inverse_square", LeaveLaw::InverseSquare}}),
                "soysal: P_l(i) = p0 (constant), p0/i (inverse) or p0/i^2 (inverse_square), i the "
                "aggregate's size"));
  keys.push_back(
      described(enum_key<LeaveSize>(
                    "controller.leave_size",
                    [](WorldSpec& w) -> LeaveSize& { return w.controller.leave_size; },
                    {{"aggregate", LeaveSize::Aggregate}, {"neighbours", LeaveSize::Neighbours}}),
                "soysal: i is the size of the tracked aggregate, or the number of perceived agents "
                "+ 1 (neighbours)"));
  keys.push_back(
      described(enum_key<CollisionMode>(
                    "controller.collision_mode",
                    [](WorldSpec& w) -> CollisionMode& { return w.controller.collision_mode; },
                    {{"ghost", CollisionMode::Ghost}, {"paper", CollisionMode::Paper}}),
                "collision: ghost agents pass through each other (an ideal gas); paper: a meeting "
                "pair aggregates and both leave at once"));
  keys.push_back(
      described(real_key(
                    "controller.tumble",
                    [](WorldSpec& w) -> double& { return w.controller.tumble; }, kProbability),
                "collision and Soysal searchers: probability per step of drawing a new heading"));
  keys.push_back(described(
      bool_key("controller.compaction.enabled",
               [](WorldSpec& w) -> bool& { return w.controller.compaction.enabled; }),
      "waiting agents close up their aggregate under a spring force (docs/controllers.md)"));
  keys.push_back(described(
      optional_real_key(
          "controller.compaction.spacing",
          [](WorldSpec& w) -> std::optional<double>& { return w.controller.compaction.spacing; },
          [](const WorldSpec& w) { return w.compaction_spacing(); }, kLength),
      "centre distance the members close up to, u; default 2 robots.radius (touching), below "
      "robots.detection_radius"));
  keys.push_back(described(
      real_key(
          "controller.compaction.gain",
          [](WorldSpec& w) -> double& { return w.controller.compaction.gain; }, kPositive),
      "speed per unit of net spring force, per tu, capped at robots.speed"));
  keys.push_back(described(
      real_key(
          "controller.compaction.tolerance",
          [](WorldSpec& w) -> double& { return w.controller.compaction.tolerance; }, kLengthOrZero),
      "net spring force below which a waiting agent stands still, u"));
  // Each registered controller's own keys follow the shared controller keys.
  for (const ControllerCatalogEntry& entry : controller_catalog()) {
    keys.insert(keys.end(), entry.keys.begin(), entry.keys.end());
  }
  keys.push_back(described(
      enum_key<EngineType>("engine.type", [](WorldSpec& w) -> EngineType& { return w.engine.type; },
                           {{"kinematic", EngineType::Kinematic}, {"box2d", EngineType::Box2D}}),
      "kinematic (exact swept encounters and contacts) or box2d (disc bodies with real contacts)"));
  keys.push_back(
      described(real_key(
                    "engine.dt", [](WorldSpec& w) -> double& { return w.engine.dt; }, kPositive),
                "length of a step, tu; probabilities per step are per dt"));
  keys.push_back(described(
      enum_key<ContactResponse>(
          "engine.contact", [](WorldSpec& w) -> ContactResponse& { return w.engine.contact; },
          {{"slide", ContactResponse::Slide}, {"stop", ContactResponse::Stop}}),
      "kinematic: a body that reaches a contact slides along it for the rest of the step, or stops "
      "there"));
  keys.push_back(described(
      real_key(
          "engine.box2d.repulsion_gain",
          [](WorldSpec& w) -> double& { return w.engine.box2d.repulsion_gain; }, kBox2dNonNegative),
      "box2d: strength of the push waiting bodies give leaving ones"));
  keys.push_back(described(
      real_key(
          "engine.box2d.linear_damping",
          [](WorldSpec& w) -> double& { return w.engine.box2d.linear_damping; }, kBox2dNonNegative),
      "box2d: linear damping of every body"));
  keys.push_back(described(
      integer_key<int>(
          "engine.box2d.velocity_iterations",
          [](WorldSpec& w) -> int& { return w.engine.box2d.velocity_iterations; }, 1, 100),
      "box2d: velocity iterations of the contact solver per Box2D step"));
  keys.push_back(described(
      integer_key<int>(
          "engine.box2d.position_iterations",
          [](WorldSpec& w) -> int& { return w.engine.box2d.position_iterations; }, 1, 100),
      "box2d: position iterations of the contact solver per Box2D step"));
  keys.push_back(
      described(integer_key<int>(
                    "engine.box2d.substeps",
                    [](WorldSpec& w) -> int& { return w.engine.box2d.substeps; }, 1, 1000),
                "box2d: Box2D steps per simulation step"));
  keys.push_back(described(
      real_key(
          "run.duration", [](WorldSpec& w) -> double& { return w.run.duration; }, kPositive),
      "simulated time of each replicate, tu; rounded to the nearest whole step of engine.dt (run "
      "and validate say so when it is not one)"));
  keys.push_back(described(
      integer_key<int>(
          "run.replicates", [](WorldSpec& w) -> int& { return w.run.replicates; }, 1, 100000),
      "number of independent replicates"));
  keys.push_back(
      described(seed_key("run.seed", [](WorldSpec& w) -> std::uint64_t& { return w.run.seed; }),
                "the run's seed; every replicate's generator key derives from it"));
  keys.push_back(described(
      integer_key<int>(
          "run.record_every", [](WorldSpec& w) -> int& { return w.run.record_every; }, 1, kMaxInt),
      "steps between two rows of timeseries.csv"));
  keys.push_back(
      described(integer_key<int>(
                    "run.threads", [](WorldSpec& w) -> int& { return w.run.threads; }, 0, 1024),
                "threads; 0: every core"));
  keys.push_back(described(
      integer_key<int>(
          "run.trajectories", [](WorldSpec& w) -> int& { return w.run.trajectories; }, 0, kMaxInt),
      "store every agent every K steps in trajectories.h5; 0: none"));
  keys.push_back(described(
      enum_key<Kappa>(
          "model.kappa", [](WorldSpec& w) -> Kappa& { return w.model.kappa; },
          {{"kinetic", Kappa::Kinetic}, {"maxwell", Kappa::Maxwell}, {"paper", Kappa::Paper}}),
      "bayindir and collision models: constant of the encounter rate kappa s v y(y-1)/A: kinetic "
      "4/pi, maxwell sqrt 2, paper (the founding paper's fitted constant) (docs/models.md)"));
  keys.push_back(described(
      enum_key<CreationVariant>(
          "model.creation", [](WorldSpec& w) -> CreationVariant& { return w.model.creation; },
          {{"original", CreationVariant::Original}, {"collision", CreationVariant::Collision}}),
      "bayindir and collision models: the creation variant marked chosen: original or collision "
      "(docs/models.md)"));
  keys.push_back(described(
      enum_key<LeavingVariant>(
          "model.leaving", [](WorldSpec& w) -> LeavingVariant& { return w.model.leaving; },
          {{"original", LeavingVariant::Original}, {"peripheral", LeavingVariant::Peripheral}}),
      "soysal model: the leaving variant marked chosen: original or peripheral (docs/models.md)"));
  keys.push_back(described(
      bool_key("model.periphery_cap", [](WorldSpec& w) -> bool& { return w.model.periphery_cap; }),
      "soysal model: cap periph(m) at m (a rim cannot hold more agents than the aggregate)"));
  keys.push_back(
      described(integer_key<int>(
                    "model.stochastic_replicates",
                    [](WorldSpec& w) -> int& { return w.model.stochastic_replicates; }, 0, 100000),
                "bayindir and collision models: replicates of the stochastic version; 0: none"));
  keys.push_back(described(
      enum_key<InitialState>("model.initial_state",
                             [](WorldSpec& w) -> InitialState& { return w.model.initial_state; },
                             {{"placement", InitialState::Placement},
                              {"placement_second_order", InitialState::PlacementSecondOrder},
                              {"all_searching", InitialState::AllSearching},
                              {"measured", InitialState::Measured}}),
      "bayindir, soysal and collision models, where predictions start: the mean first decision "
      "of sampled placements, its "
      "second-order formula (sparse placements only), all agents searching, or the state a run "
      "measured"));
  keys.push_back(described(
      optional_real_key(
          "rates.return_window",
          [](WorldSpec& w) -> std::optional<double>& { return w.rates.return_window; },
          [](const WorldSpec& w) { return w.return_window(); }, kPositive),
      "tu after a LEAVE attempt within which waiting again beside a member of the aggregate left "
      "that kept waiting counts as a return (default 3 leave timeouts; 3 steps when "
      "controller.leave_timeout is 0)"));
  keys.push_back(described(
      integer_key<int>(
          "render.every", [](WorldSpec& w) -> int& { return w.render.every; }, 0, kMaxInt),
      "draw a frame every K steps; 0: none"));
  keys.push_back(
      described(integer_key<int>(
                    "render.width", [](WorldSpec& w) -> int& { return w.render.width; }, 32, 8192),
                "frame width, pixels"));
  keys.push_back(described(
      integer_key<int>(
          "render.height", [](WorldSpec& w) -> int& { return w.render.height; }, 32, 8192),
      "frame height, pixels"));
  keys.push_back(described(
      integer_key<int>(
          "render.replicate", [](WorldSpec& w) -> int& { return w.render.replicate; }, 0, 100000),
      "the replicate whose frames are drawn"));
  keys.push_back(
      described(string_key("render.dir", [](WorldSpec& w) -> std::string& { return w.render.dir; }),
                "folder for the frames; empty: <out>/frames/ with --out, else renders/<name>/"));
  return keys;
}

}  // namespace

namespace {

// A controller's own key: its value lives in ControllerSpec::parameters under `path`.
template <typename T>
WorldKey controller_key(std::string path, std::string type, std::string expected, T fallback,
                        std::function<T(const YAML::Node&)> parse,
                        std::function<YAML::Node(const T&)> show, std::string controller) {
  auto read = [path, parse](WorldSpec& w, const YAML::Node& node) {
    w.controller.parameters[path] = parse(node);
  };
  auto write = [path, fallback, show](const WorldSpec& w) {
    const auto found = w.controller.parameters.find(path);
    return show(found == w.controller.parameters.end() ? fallback : std::get<T>(found->second));
  };
  return {std::move(path), std::move(type),       std::move(expected), read,
          write,           std::move(controller), std::move(fallback), {}};
}

template <typename T>
const T& controller_value(const WorldSpec& spec, const WorldKey& key) {
  const auto found = spec.controller.parameters.find(key.path);
  return std::get<T>(found == spec.controller.parameters.end() ? key.default_value : found->second);
}

YAML::Node show_number(const double& value) {
  return YAML::Node(format_number(value));
}

}  // namespace

WorldKey number_key(std::string path, double fallback, double low, double high,
                    std::string controller) {
  const RealBounds bounds{low, true, high,
                          "a number from " + format_number(low) + " to " + format_number(high)};
  return controller_key<double>(
      std::move(path), "number", bounds.expected, fallback,
      [bounds](const YAML::Node& node) { return read_bounded_real(node, bounds); }, show_number,
      std::move(controller));
}

WorldKey whole_number_key(std::string path, long long fallback, long long low, long long high,
                          std::string controller) {
  const std::string expected = whole_expected(low, high);
  return controller_key<double>(
      std::move(path), "integer", expected, static_cast<double>(fallback),
      [low, high, expected](const YAML::Node& node) {
        return static_cast<double>(read_whole(node, low, high, expected));
      },
      show_number, std::move(controller));
}

WorldKey probability_key(std::string path, double fallback, std::string controller) {
  return controller_key<double>(
      std::move(path), "probability", kProbability.expected, fallback,
      [](const YAML::Node& node) { return read_bounded_real(node, kProbability); }, show_number,
      std::move(controller));
}

WorldKey name_choice_key(std::string path, std::string fallback, std::vector<std::string> names,
                         std::string controller) {
  const std::string expected = choice_expected(names);
  return controller_key<std::string>(
      std::move(path), "choice", expected, std::move(fallback),
      [names, expected](const YAML::Node& node) {
        std::string text = scalar_text(node, expected);
        if (std::find(names.begin(), names.end(), text) == names.end()) {
          throw KeyValueError{expected};
        }
        return text;
      },
      [](const std::string& name) { return YAML::Node(name); }, std::move(controller));
}

WorldKey flag_key(std::string path, bool fallback, std::string controller) {
  return controller_key<bool>(
      std::move(path), "boolean", kFlagExpected, fallback, read_flag,
      [](const bool& on) { return YAML::Node(on ? "true" : "false"); }, std::move(controller));
}

namespace {

// One item of a list as a message shows it: its text, or what it is instead of a number.
}  // namespace

WorldKey number_list_key(std::string path, std::vector<double> fallback, double low, double high,
                         std::string controller) {
  const std::string expected = "a list of one or more numbers from " + format_number(low) + " to " +
                               format_number(high) + ", e.g. [" + format_number(low) + ", " +
                               format_number(high) + "]";
  return controller_key<std::vector<double>>(
      std::move(path), "list of numbers", expected, std::move(fallback),
      [low, high, expected](const YAML::Node& node) {
        if (!node.IsSequence() || node.size() == 0) throw KeyValueError{expected};
        std::vector<double> values;
        for (const YAML::Node& item : node) {
          // The item at fault is named: "got a list" alone reads as if lists were refused.
          auto wrong_item = [&] {
            return KeyValueError{expected, "a list whose item " +
                                               std::to_string(values.size() + 1) + " is " +
                                               shown_item(item)};
          };
          double v = 0.0;
          try {
            v = read_real(item, expected);
          } catch (const KeyValueError&) {
            throw wrong_item();
          }
          if (!(v >= low && v <= high)) throw wrong_item();
          values.push_back(v);
        }
        return values;
      },
      [](const std::vector<double>& values) {
        YAML::Node list(YAML::NodeType::Sequence);
        list.SetStyle(YAML::EmitterStyle::Flow);
        for (const double v : values) list.push_back(format_number(v));
        return list;
      },
      std::move(controller));
}

double number(const WorldSpec& spec, const WorldKey& key) {
  return controller_value<double>(spec, key);
}

long long whole_number(const WorldSpec& spec, const WorldKey& key) {
  return static_cast<long long>(controller_value<double>(spec, key));
}

const std::string& name_choice(const WorldSpec& spec, const WorldKey& key) {
  return controller_value<std::string>(spec, key);
}

bool flag(const WorldSpec& spec, const WorldKey& key) {
  return controller_value<bool>(spec, key);
}

WorldKey described(WorldKey key, std::string meaning) {
  key.meaning = std::move(meaning);
  return key;
}

const std::vector<double>& number_list(const WorldSpec& spec, const WorldKey& key) {
  return controller_value<std::vector<double>>(spec, key);
}

std::string format_number(double value) {
  // Plain decimals read best in world files (0.0001, not 1e-04); very large or very small
  // magnitudes keep the exponent. Both are the shortest text that reads back exactly.
  const double magnitude = std::fabs(value);
  const bool plain = magnitude == 0.0 || (magnitude >= 1e-6 && magnitude < 1e15);
  char buffer[400];
  const auto result =
      plain ? std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed)
            : std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

const std::vector<WorldKey>& world_keys() {
  static const std::vector<WorldKey> keys = build_keys();
  return keys;
}

const WorldKey* find_world_key(const std::string& path) {
  for (const WorldKey& key : world_keys()) {
    if (key.path == path) return &key;
  }
  return nullptr;
}

const std::vector<std::string>& world_blocks() {
  static const std::vector<std::string> blocks = {
      "arena", "robots", "controller", "controller.compaction", "engine", "engine.box2d", "run",
      "model", "rates",  "render"};
  return blocks;
}

std::vector<std::string> world_key_paths() {
  std::vector<std::string> paths;
  for (const WorldKey& key : world_keys()) paths.push_back(key.path);
  return paths;
}

}  // namespace swarmagg
