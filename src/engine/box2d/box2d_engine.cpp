#include "engine/box2d/box2d_engine.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "control_interface/command_check.hpp"
#include "core/errors.hpp"
#include "engine/box2d/contact_rules.hpp"
#include "engine/box2d/fixture_tags.hpp"
#include "engine/box2d/periodic_body.hpp"
#include "engine/box2d/sensor_links.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {
namespace {

using box2d::AgentControls;
using box2d::BodyShapes;
using box2d::ContactRules;
using box2d::FixtureRole;
using box2d::PeriodicBody;
using box2d::SensorLink;
using box2d::SensorLinks;
using box2d::WallSide;

// Box2D clamps a body's translation to b2_maxTranslation (2 u) per b2World::Step, silently,
// and only finds a contact between two moving bodies once they overlap. Every step is cut
// into enough substeps that no body travels more than half of the cap, nor more than half
// its radius, in one: never clamped, two bodies overlap by at most r when they first touch
// and never tunnel through each other; the torus images reach that much ahead of a body.
constexpr double kMaxSubstepTravelCap = 0.5 * b2_maxTranslation;
constexpr int kMaxSubsteps = 4096;

double max_travel_per_substep(const WorldSpec& spec) {
  return std::min(kMaxSubstepTravelCap, 0.5 * spec.robots.radius);
}
// The repulsion force on a leaving body whose centre is 2r from one waiting body's (touching):
// `gain` (1 - 2r/s), per unit mass. More repellers, or overlap, push harder.
double touching_push(const WorldSpec& spec) {
  return spec.engine.box2d.repulsion_gain *
         std::max(0.0, 1.0 - 2.0 * spec.robots.radius / spec.robots.detection_radius);
}
// The substeps a step needs for a body at full speed that one touching repeller pushes for the
// whole step (substeps_for counts the same at run time, for the real forces): a gain that
// fails this would fail every run at its first leave.
double touching_push_substeps(const WorldSpec& spec) {
  return (spec.robots.speed + spec.engine.dt * touching_push(spec)) * spec.engine.dt /
         max_travel_per_substep(spec);
}
constexpr double kWallThickness = 10.0;

// Box2D keeps positions in single precision, which rounds every move to the spacing of floats
// at the arena's far side: a move of k spacings comes out up to half a spacing long or short
// (an arena 999,999 wide gave agents speeds from 0.77 to 1.26 v). A substep's move at the
// nominal speed (the configured substeps, or more where a step would travel too far) of at
// least kMoveSpacings spacings keeps speeds within 1 %. Empty when it does.
std::string too_coarse_for_moves(const WorldSpec& spec) {
  constexpr double kMoveSpacings = 50.0;
  const auto far = static_cast<float>(std::max(spec.arena.width, spec.arena.height));
  const double spacing = std::nextafter(far, std::numeric_limits<float>::infinity()) - far;
  const double step = spec.robots.speed * spec.engine.dt;
  const double substeps = std::max(static_cast<double>(spec.engine.box2d.substeps),
                                   std::ceil(step / max_travel_per_substep(spec)));
  const double move = step / substeps;
  if (spec.robots.speed <= 0.0 || move >= kMoveSpacings * spacing) return "";
  char text[512];
  std::snprintf(text, sizeof text,
                "engine.type: box2d keeps positions in single precision: in an arena %g wide a "
                "substep moves an agent %g (robots.speed * engine.dt over %g substeps), %.3g "
                "times the spacing of positions there (%g), and needs %g times to keep speeds "
                "within 1 %%; use the kinematic engine, a smaller arena or a longer engine.dt",
                static_cast<double>(far), move, substeps, move / spacing, spacing, kMoveSpacings);
  return text;
}

b2Vec2 to_b2(Vec2 v) {
  return {static_cast<float>(v.x), static_cast<float>(v.y)};
}
Vec2 from_b2(b2Vec2 v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y)};
}

// Box2D 2.4 fills its table of contact constructors lazily, on the first contact any world
// creates, without a lock: replicates starting in parallel threads would race on it. Run one
// contact once, under the thread-safe initialisation of a function-local static.
void initialise_box2d_once() {
  static const bool done = [] {
    b2World world(b2Vec2(0.0f, 0.0f));
    b2CircleShape circle;
    circle.m_radius = 1.0f;
    for (int i = 0; i < 2; ++i) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position.Set(0.5f * static_cast<float>(i), 0.0f);
      world.CreateBody(&def)->CreateFixture(&circle, 1.0f);
    }
    world.Step(0.0f, 1, 1);
    return true;
  }();
  (void)done;
}

class Box2DEngine final : public Engine {
 public:
  Box2DEngine(const WorldSpec& spec, std::span<const Vec2> initial_positions);
  Box2DEngine(const Box2DEngine&) = delete;
  Box2DEngine& operator=(const Box2DEngine&) = delete;

  StepReport step(std::span<const MotionCommand> commands,
                  std::span<const Signal> signals) override;
  std::span<const Vec2> positions() const override { return positions_; }
  const NeighbourLists& neighbours() const override { return neighbours_; }
  std::span<const std::uint8_t> reflections() const override { return reflections_; }

 private:
  std::size_t size() const { return bodies_.size(); }
  Vec2 body_position(AgentId agent) const { return from_b2(bodies_[agent].body()->GetPosition()); }
  void create_walls();
  void apply_signals(std::span<const MotionCommand> commands, std::span<const Signal> signals);
  void compute_repulsion();
  int substeps_for(std::span<const MotionCommand> commands) const;
  void apply_forces(float h);
  void wrap_bodies();
  void collect(std::span<const MotionCommand> commands);

  ArenaGeometry geometry_;
  double dt_;
  double fastest_command2_;  // the squared speed limit of commands (command_check.hpp)
  double detection_radius_;
  double sensing_radius_;
  double repulsion_gain_;
  int min_substeps_;
  double max_travel_;  // per body and substep
  int velocity_iterations_;
  int position_iterations_;
  BodyShapes shapes_;

  // Declared before the world so that the world, whose callbacks use them, dies first.
  AgentControls controls_;
  SensorLinks links_;
  std::vector<PeriodicBody> bodies_;
  ContactRules rules_;
  std::unique_ptr<b2World> world_;
  b2Body* walls_ = nullptr;

  std::vector<AgentId> repelled_;  // agents whose command has a repelled_by this step
  std::vector<AgentId> forced_;    // agents with a nonzero force this substep
  std::vector<Vec2> forces_;       // per agent; zero for every agent not in forced_
  std::vector<Vec2> positions_;
  NeighbourLists neighbours_;
  std::vector<std::uint8_t> reflections_;
};

void check_spec(const WorldSpec& spec, const BodyShapes& shapes) {
  const Box2DSpec& b = spec.engine.box2d;
  std::ostringstream why;
  if (!(spec.engine.dt > 0.0))
    why << "engine.dt must be > 0";
  else if (b.substeps < 1)
    why << "engine.box2d.substeps must be >= 1";
  else if (b.velocity_iterations < 1 || b.position_iterations < 1)
    why << "engine.box2d.velocity_iterations and position_iterations must be >= 1";
  else if (!(spec.robots.radius > 0.0))
    why << "robots.radius must be > 0";
  else if (!(spec.robots.detection_radius > 0.0))
    why << "robots.detection_radius must be > 0";
  else if (b.repulsion_gain < 0.0 || b.linear_damping < 0.0)
    why << "engine.box2d.repulsion_gain and linear_damping must be >= 0";
  else if (spec.robots.speed * spec.engine.dt / max_travel_per_substep(spec) > kMaxSubsteps)
    why << "robots.speed * engine.dt = " << spec.robots.speed * spec.engine.dt
        << " u per step would need more than " << kMaxSubsteps
        << " Box2D substeps (the engine moves a body at most min(" << kMaxSubstepTravelCap
        << ", robots.radius / 2) u per substep; Box2D itself caps it at " << b2_maxTranslation
        << ")";
  else if (touching_push_substeps(spec) > kMaxSubsteps)
    why << "engine.box2d.repulsion_gain = " << b.repulsion_gain
        << " pushes a leaving body touching one waiting body to "
        << spec.robots.speed + spec.engine.dt * touching_push(spec)
        << " u/tu within a step, which would need more than " << kMaxSubsteps
        << " Box2D substeps (at most min(" << kMaxSubstepTravelCap
        << ", robots.radius / 2) u each); lower it";
  else if (const std::string coarse = too_coarse_for_moves(spec); !coarse.empty())
    why << coarse;
  else if (shapes.torus && std::min(spec.arena.width, spec.arena.height) <=
                               2.0 * static_cast<double>(shapes.sensor_keep_margin))
    why << "a torus arena must be wider and higher than " << 2.0 * shapes.sensor_keep_margin
        << " for the Box2D engine (twice the sensing radius plus "
        << 2.0 * (shapes.sensor_keep_margin - spec.sensing_radius())
        << ": the periodic images of two edges must not meet)";
  if (!why.str().empty()) {
    throw InputError((spec.source.empty() ? spec.name : spec.source) + ": " + why.str());
  }
}

BodyShapes shapes_for(const WorldSpec& spec) {
  BodyShapes shapes;
  const double s = spec.robots.detection_radius;
  const double sensing = std::max(spec.sensing_radius(), s);
  shapes.solid_radius = static_cast<float>(spec.robots.radius);
  shapes.detect_radius = static_cast<float>(0.5 * s);
  shapes.sense_radius = sensing > s ? static_cast<float>(0.5 * sensing) : 0.0f;
  shapes.width = static_cast<float>(spec.arena.width);
  shapes.height = static_cast<float>(spec.arena.height);
  shapes.torus = spec.arena.topology == Topology::Torus;
  // A pair senses across the seam only when both centres are within `sensing` of it, and
  // touches only within 2r; a body moves at most max_travel_per_substep() between two image
  // updates (0.1 u spare for float rounding; 0.5 u of hysteresis).
  const double travel = max_travel_per_substep(spec) + 0.1;
  shapes.sensor_add_margin = static_cast<float>(sensing + travel);
  shapes.sensor_keep_margin = shapes.sensor_add_margin + 0.5f;
  shapes.solid_add_margin =
      std::min(shapes.sensor_add_margin, static_cast<float>(2.0 * spec.robots.radius + travel));
  shapes.solid_keep_margin = std::min(shapes.sensor_keep_margin, shapes.solid_add_margin + 0.5f);
  shapes.linear_damping = static_cast<float>(spec.engine.box2d.linear_damping);
  return shapes;
}

Box2DEngine::Box2DEngine(const WorldSpec& spec, std::span<const Vec2> initial_positions)
    : geometry_(spec.arena.geometry()),
      dt_(spec.engine.dt),
      fastest_command2_(fastest_command_speed2(geometry_, spec.sensing_radius(), dt_)),
      detection_radius_(spec.robots.detection_radius),
      sensing_radius_(std::max(spec.sensing_radius(), spec.robots.detection_radius)),
      repulsion_gain_(spec.engine.box2d.repulsion_gain),
      min_substeps_(spec.engine.box2d.substeps),
      max_travel_(max_travel_per_substep(spec)),
      velocity_iterations_(spec.engine.box2d.velocity_iterations),
      position_iterations_(spec.engine.box2d.position_iterations),
      shapes_(shapes_for(spec)),
      rules_(controls_, links_, bodies_) {
  check_spec(spec, shapes_);
  initialise_box2d_once();
  const std::size_t n = initial_positions.size();
  controls_.resize(n);
  links_.reset(n);
  forces_.assign(n, Vec2{});
  repelled_.reserve(n);
  forced_.reserve(n);
  positions_.assign(n, Vec2{});
  reflections_.assign(n, 0);

  world_ = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
  world_->SetAllowSleeping(false);
  // Continuous collision only matters against static bodies (the walls); without walls it
  // would only scan every contact once more per step.
  world_->SetContinuousPhysics(!shapes_.torus);
  world_->SetContactFilter(&rules_);
  world_->SetContactListener(&rules_);

  bodies_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 p = geometry_.wrap(initial_positions[i]);
    if (!shapes_.torus &&
        (p.x < 0.0 || p.x > geometry_.width() || p.y < 0.0 || p.y > geometry_.height())) {
      throw InputError("agent " + std::to_string(i) + " is placed outside the walled arena");
    }
    bodies_[i].create(*world_, static_cast<AgentId>(i), to_b2(p), shapes_);
  }
  if (!shapes_.torus) create_walls();

  // A step of zero length runs only Box2D's contact update: the overlaps of the initial
  // placement become sensor links (neither encounters nor halts).
  world_->Step(0.0f, velocity_iterations_, position_iterations_);
  collect({});
}

void Box2DEngine::create_walls() {
  b2BodyDef def;
  def.type = b2_staticBody;
  walls_ = world_->CreateBody(&def);
  const float w = shapes_.width;
  const float h = shapes_.height;
  const float t = static_cast<float>(kWallThickness);
  struct Box {
    WallSide side;
    b2Vec2 half;
    b2Vec2 centre;
  };
  const Box boxes[] = {
      {WallSide::Left, {0.5f * t, 0.5f * h + t}, {-0.5f * t, 0.5f * h}},
      {WallSide::Right, {0.5f * t, 0.5f * h + t}, {w + 0.5f * t, 0.5f * h}},
      {WallSide::Bottom, {0.5f * w + t, 0.5f * t}, {0.5f * w, -0.5f * t}},
      {WallSide::Top, {0.5f * w + t, 0.5f * t}, {0.5f * w, h + 0.5f * t}},
  };
  for (const Box& box : boxes) {
    b2PolygonShape shape;
    shape.SetAsBox(box.half.x, box.half.y, box.centre, 0.0f);
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.friction = 0.0f;
    fixture.restitution = 0.0f;
    fixture.filter = box2d::filter_for(FixtureRole::Wall);
    fixture.userData.pointer =
        box2d::encode_tag({static_cast<AgentId>(box.side), FixtureRole::Wall});
    walls_->CreateFixture(&fixture);
  }
}

void Box2DEngine::apply_signals(std::span<const MotionCommand> commands,
                                std::span<const Signal> signals) {
  bool refiltered = false;
  repelled_.clear();
  for (std::size_t i = 0; i < size(); ++i) {
    const MotionCommand& c = commands[i];
    controls_.halt_on[i] = c.halt_on;
    controls_.repelled_by[i] = c.repelled_by;
    controls_.halted[i] = 0;
    if (c.repelled_by != 0) repelled_.push_back(static_cast<AgentId>(i));
    if (signals[i] == controls_.signal[i] && c.blocked_by == controls_.blocked_by[i]) continue;
    controls_.signal[i] = signals[i];
    controls_.blocked_by[i] = c.blocked_by;
    bodies_[i].refilter_solids();
    refiltered = true;
  }
  if (refiltered) {
    // Refiltering drops contacts that are no longer solid at the next contact update, but
    // pairs that just became solid would only be found after the coming solver pass. Find
    // them now so a body cannot sink into a neighbour it was just told to respect. (The
    // contact manager is a non-const member of the non-const world: the cast is safe.)
    const_cast<b2ContactManager&>(world_->GetContactManager()).FindNewContacts();
  }
}

void Box2DEngine::compute_repulsion() {
  for (const AgentId i : forced_) forces_[i] = Vec2{};
  forced_.clear();
  if (repulsion_gain_ <= 0.0) return;
  const double s = detection_radius_;
  for (const AgentId i : repelled_) {
    if (controls_.halted[i]) continue;
    const SignalMask repelled_by = controls_.repelled_by[i];
    const Vec2 pi = body_position(i);
    Vec2 force;
    for (const SensorLink& link : links_.of(i)) {
      if ((repelled_by & mask_of(controls_.signal[link.other])) == 0) continue;
      const Vec2 d = geometry_.displacement(pi, body_position(link.other));
      const double distance = norm(d);
      if (distance >= s || distance <= 0.0) continue;
      // Linear in the distance: `gain` (per unit mass) at contact of the centres, 0 at s.
      force += d * (-repulsion_gain_ * (1.0 - distance / s) / distance);
    }
    if (force.x == 0.0 && force.y == 0.0) continue;
    forces_[i] = force;
    forced_.push_back(i);
  }
}

int Box2DEngine::substeps_for(std::span<const MotionCommand> commands) const {
  double fastest2 = 0.0;
  bool within = true;
  for (const MotionCommand& c : commands) {
    const double speed2 = norm2(c.velocity);
    fastest2 = std::max(fastest2, speed2);
    within &= command_within(speed2, fastest_command2_);
  }
  if (!within) refuse_bad_command(commands, fastest_command2_, dt_);
  double pushed2 = 0.0;
  AgentId most_pushed = 0;
  for (const AgentId i : forced_) {
    const double speed2 = norm2(commands[i].velocity + forces_[i] * dt_);
    if (speed2 > pushed2) {
      pushed2 = speed2;
      most_pushed = i;
    }
  }
  const double fastest = std::sqrt(std::max(fastest2, pushed2));
  const double needed = std::ceil(fastest * dt_ / max_travel_);
  if (needed > kMaxSubsteps) {
    const std::string speed = std::to_string(fastest) + " u/tu, which needs more than " +
                              std::to_string(kMaxSubsteps) + " Box2D substeps per step";
    // A speed the controller commanded is its fault, named with it (Replicate).
    if (pushed2 <= fastest2) throw BadCommand("commanded a speed of " + speed);
    throw std::runtime_error("Box2D engine: the repulsion push on leaving agent " +
                             std::to_string(most_pushed) + " reaches " + speed +
                             " (lower engine.box2d.repulsion_gain)");
  }
  return std::max(min_substeps_, static_cast<int>(needed));
}

void Box2DEngine::apply_forces(float h) {
  // Commanded velocities were checked by substeps_for and contacts cannot speed a body up
  // beyond them; forces can: check what Box2D will integrate before its contact solver.
  constexpr float kCap = 0.999f * b2_maxTranslation;
  const float inv_damping = 1.0f / (1.0f + h * shapes_.linear_damping);
  for (const AgentId i : forced_) {
    b2Body* body = bodies_[i].body();
    const b2Vec2 force = to_b2(forces_[i]);
    body->ApplyForceToCenter(force, true);
    const b2Vec2 v = inv_damping * (body->GetLinearVelocity() + h * force);
    if (h * h * v.LengthSquared() > kCap * kCap) {
      // The substeps were counted from the pushes at the step's start; more waiting bodies
      // can come to push within it.
      char text[400];
      std::snprintf(text, sizeof text,
                    "Box2D engine: agent %u would move %.3g u in one Box2D step, pushed by the "
                    "waiting bodies around it (engine.box2d.repulsion_gain %g); Box2D would clamp "
                    "it to %g u: lower engine.box2d.repulsion_gain or raise engine.box2d.substeps",
                    i, h * v.Length(), repulsion_gain_, b2_maxTranslation);
      throw std::runtime_error(text);
    }
  }
}

void Box2DEngine::wrap_bodies() {
  if (!shapes_.torus) return;
  for (PeriodicBody& body : bodies_) body.follow_torus();
}

StepReport Box2DEngine::step(std::span<const MotionCommand> commands,
                             std::span<const Signal> signals) {
  if (commands.size() != size() || signals.size() != size()) {
    throw std::invalid_argument("Box2D engine: one command and one signal per agent expected");
  }
  apply_signals(commands, signals);
  for (std::size_t i = 0; i < size(); ++i) {
    bodies_[i].body()->SetLinearVelocity(to_b2(commands[i].velocity));
  }
  compute_repulsion();
  const int substeps = substeps_for(commands);
  const float h = static_cast<float>(dt_ / substeps);

  rules_.start_step();
  for (int k = 0; k < substeps; ++k) {
    if (k > 0) compute_repulsion();
    apply_forces(h);
    // Box2D first updates contacts (sensor events of the previous substep's motion fire
    // here, and guarded moves stop their bodies), then solves and moves the bodies.
    world_->Step(h, velocity_iterations_, position_iterations_);
    wrap_bodies();
  }
  // Contact update only: the sensor events of the last substep's motion.
  world_->Step(0.0f, velocity_iterations_, position_iterations_);
  const std::uint64_t encounters = rules_.finish_step();
  collect(commands);
  return {encounters};
}

void Box2DEngine::collect(std::span<const MotionCommand> commands) {
  const std::size_t n = size();
  for (std::size_t i = 0; i < n; ++i) {
    positions_[i] = geometry_.wrap(body_position(static_cast<AgentId>(i)));
  }
  const bool separate_sense = shapes_.sense_radius > 0.0f;
  neighbours_.reset(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto agent = static_cast<AgentId>(i);
    for (const SensorLink& link : links_.of(agent)) {
      if ((separate_sense ? link.sense : link.detect) == 0) continue;
      // Box2D's sensors work in float; the exact test is on the centre distance.
      const Vec2 d = geometry_.displacement(positions_[i], positions_[link.other]);
      const double distance = norm(d);
      if (distance <= sensing_radius_) neighbours_.push({link.other, d, distance});
    }
    neighbours_.close_agent(agent);
  }

  std::fill(reflections_.begin(), reflections_.end(), std::uint8_t{0});
  if (walls_ == nullptr || commands.empty()) return;
  for (b2ContactEdge* edge = walls_->GetContactList(); edge != nullptr; edge = edge->next) {
    b2Contact* contact = edge->contact;
    if (!contact->IsTouching()) continue;
    box2d::FixtureTag wall = box2d::tag_of(contact->GetFixtureA());
    box2d::FixtureTag agent = box2d::tag_of(contact->GetFixtureB());
    if (wall.role != FixtureRole::Wall) std::swap(wall, agent);
    const Vec2 v = commands[agent.agent].velocity;
    // Box2D stops the body at the wall; the bumper bit lets the controller turn its heading
    // the way the kinematic engine's reflection does.
    switch (static_cast<WallSide>(wall.agent)) {
      case WallSide::Left:
        if (v.x < 0.0) reflections_[agent.agent] |= ReflectedX;
        break;
      case WallSide::Right:
        if (v.x > 0.0) reflections_[agent.agent] |= ReflectedX;
        break;
      case WallSide::Bottom:
        if (v.y < 0.0) reflections_[agent.agent] |= ReflectedY;
        break;
      case WallSide::Top:
        if (v.y > 0.0) reflections_[agent.agent] |= ReflectedY;
        break;
    }
  }
}

}  // namespace

std::unique_ptr<Engine> make_box2d_engine(const WorldSpec& spec,
                                          std::span<const Vec2> initial_positions) {
  return std::make_unique<Box2DEngine>(spec, initial_positions);
}

void check_box2d_world(const WorldSpec& spec) {
  check_spec(spec, shapes_for(spec));
}

}  // namespace swarmagg
