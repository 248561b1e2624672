#pragma once
// The immutable description of a world, parsed once from YAML (config/world_loader) and
// shared read-only by every replicate, engine, controller, observer and model. Every field
// has the default docs/reference/world-keys.md lists; the key registry (config/world_keys) maps the
// dotted YAML key paths onto these fields.
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "geometry/arena_geometry.hpp"

namespace swarmagg {

enum class IsolatedWait { Resume, Stay };
enum class LeaveLaw { Constant, Inverse, InverseSquare };
enum class LeaveSize { Aggregate, Neighbours };
enum class CollisionMode { Ghost, Paper };
enum class EngineType { Kinematic, Box2D };
// How a body moving into a body solid to it goes on (kinematic engine; Box2D's contacts
// always slide): along the contact for the rest of the step, or halted there.
enum class ContactResponse { Slide, Stop };
enum class Kappa { Kinetic, Maxwell, Paper };
enum class CreationVariant { Original, Collision };
enum class LeavingVariant { Original, Peripheral };
// Where the models start (docs/models.md): the state after the first decision, i.e. the
// aggregates that the placement formed at once (the mean over sampled placements, its
// second-order formula, or the mean a run measured), or all agents searching as the paper's
// models did.
enum class InitialState { Placement, PlacementSecondOrder, AllSearching, Measured };

struct ArenaSpec {
  double width = 180.0;
  double height = 180.0;
  Topology topology = Topology::Torus;
  double area() const { return width * height; }
  ArenaGeometry geometry() const { return {width, height, topology}; }
};

struct PlacedAgent {
  double x = 0.0;
  double y = 0.0;
  double heading_deg = 0.0;  // counter-clockwise from +x
  friend bool operator==(const PlacedAgent&, const PlacedAgent&) = default;
};

struct RobotsSpec {
  int count = 150;
  double radius = 1.0;                 // r, body radius
  double detection_radius = 4.0;       // s, centre to centre
  double speed = 1.0;                  // v
  std::vector<PlacedAgent> placement;  // empty: uniform random placement
  bool random_placement() const { return placement.empty(); }
};

// docs/controllers.md, "Compaction": waiting agents close up their aggregate under a spring force.
struct CompactionSpec {
  bool enabled = true;
  std::optional<double> spacing;  // u, centre to centre; unset: 2 robots.radius (touching)
  double gain = 1.0;              // per tu: speed per unit of net spring force, capped at v
  double tolerance = 0.05;        // u: a net force below it leaves the agent standing
};

// The value of a registered controller's own key (config/world_keys.hpp builds them): a
// number (integers too, exactly up to 2^53), a flag, a name or a list of numbers.
using ControllerValue = std::variant<double, bool, std::string, std::vector<double>>;

struct ControllerSpec {
  std::string type = "bayindir";  // a registered controller (config/controller_catalog.hpp)
  double p_leave = 0.0;           // bayindir: per step
  double leave_timeout = 10.0;    // tu
  bool join = true;
  bool leave = true;
  IsolatedWait isolated_wait = IsolatedWait::Resume;
  double approach_radius = 12.0;  // soysal: s_a
  double p0 = 0.00002;            // soysal: per step
  LeaveLaw leave_law = LeaveLaw::Constant;
  LeaveSize leave_size = LeaveSize::Aggregate;
  CollisionMode collision_mode = CollisionMode::Ghost;
  double tumble = 0.0;  // collision: heading redraw probability per step
  CompactionSpec compaction;
  // The keys of controllers registered with their own keys (controller.<name> -> values), so a
  // new controller adds no field here. Absent: the key's default.
  std::map<std::string, ControllerValue> parameters;
};

struct Box2DSpec {
  double repulsion_gain = 20.0;  // force per unit mass at zero distance, fading to 0 at s
  double linear_damping = 0.0;
  int velocity_iterations = 8;
  int position_iterations = 3;
  int substeps = 1;  // Box2D steps per simulation step
};

struct EngineSpec {
  EngineType type = EngineType::Kinematic;
  double dt = 0.1;
  ContactResponse contact = ContactResponse::Slide;
  Box2DSpec box2d;
};

struct RunSpec {
  double duration = 5000.0;  // tu
  int replicates = 10;
  std::uint64_t seed = 1;
  int record_every = 10;  // steps between recorded rows
  int threads = 0;        // 0: as many as the machine has
  int trajectories = 0;   // steps between rows of trajectories.h5; 0: no trajectory file
};

struct ModelSpec {
  Kappa kappa = Kappa::Kinetic;
  CreationVariant creation = CreationVariant::Collision;
  LeavingVariant leaving = LeavingVariant::Peripheral;
  bool periphery_cap = true;
  int stochastic_replicates = 10;
  InitialState initial_state = InitialState::Placement;
};

// What `rates` measures beyond the model terms: returns (docs/models-returns.md).
struct RatesSpec {
  // tu after a LEAVE attempt starts within which coming back counts as a return; unset:
  // three leave timeouts.
  std::optional<double> return_window;
};

struct RenderSpec {
  int every = 0;  // 0: no frames
  int width = 800;
  int height = 800;
  int replicate = 0;
  std::string dir;  // empty: renders/<world name>/, or <out>/frames/ when --out is given
};

struct WorldSpec {
  std::string name = "world";
  std::string source;  // the file it was loaded from, for messages
  ArenaSpec arena;
  RobotsSpec robots;
  ControllerSpec controller;
  EngineSpec engine;
  RunSpec run;
  ModelSpec model;
  RatesSpec rates;
  RenderSpec render;

  // The distance compaction closes waiting members up to (2r unless the world sets it).
  double compaction_spacing() const {
    return controller.compaction.spacing.value_or(2.0 * robots.radius);
  }
  // The tu within which a leaver that comes back counts as returning (rates.return_window).
  // Default: 3 leave timeouts; 3 steps for a timeout of 0, so that the window is a positive
  // number world.resolved.yaml can hold (and a leaver back at once counts as a return).
  double return_window() const {
    return rates.return_window.value_or(
        3.0 * (controller.leave_timeout > 0.0 ? controller.leave_timeout : engine.dt));
  }
  // Number of steps a replicate runs: duration / dt, rounded to the nearest step.
  std::int64_t steps() const { return std::llround(run.duration / engine.dt); }
  // Says how long a replicate runs when run.duration is not a whole number of steps (a
  // world's duration kept while its engine.dt changes), "" when it is.
  std::string rounded_duration_note() const;
  // The largest radius any sensor of this world's controller reads (the controller says).
  double sensing_radius() const;
  // How far agents perceive one another: 0 when the controller reads no neighbours (ghost
  // collisions only count encounters, which the engine detects), so that an engine need not
  // build lists nobody reads.
  double perception_radius() const;
};

}  // namespace swarmagg
