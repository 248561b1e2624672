#include "bench/lib/box2d_bench.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "config/world_spec.hpp"
#include "core/rng.hpp"
#include "core/thread_clock.hpp"
#include "engine/box2d/box2d_engine.hpp"
#include "engine/box2d/fixture_tags.hpp"
#include "geometry/pair_finder.hpp"

namespace swarmagg {
namespace {

constexpr double kPaperDensity = 150.0 / (180.0 * 180.0);
constexpr double kRadius = 1.0;
constexpr double kDetection = 4.0;
constexpr double kSpeed = 1.0;
constexpr double kDt = 0.1;
constexpr int kWarmup = 10;

struct Scene {
  double side = 0.0;
  std::vector<Vec2> positions;
  std::vector<Vec2> velocities;
};

// Uniform positions at least 2r apart (rejection sampling), random headings.
Scene make_scene(int n) {
  Scene scene;
  scene.side = std::sqrt(n / kPaperDensity);
  const CounterRng rng(0xB0C5);
  const double contact = 2.0 * kRadius;
  PairFinder placed;
  placed.reset(ArenaGeometry(scene.side, scene.side, Topology::Torus), contact,
               static_cast<std::size_t>(n));
  std::uint64_t draw = 0;
  while (static_cast<int>(scene.positions.size()) < n) {
    const Vec2 p{scene.side * rng.uniform(draw, 0, Draw::Placement),
                 scene.side * rng.uniform(draw, 1, Draw::Placement)};
    ++draw;
    bool free = true;
    placed.for_each_near(
        p, [&](std::uint32_t, Vec2 d) { free = free && norm2(d) >= contact * contact; });
    if (!free) continue;
    placed.add(p);
    scene.positions.push_back(p);
    const double angle = 6.283185307179586 * rng.uniform(draw, 2, Draw::Heading);
    scene.velocities.push_back(from_angle(angle) * kSpeed);
  }
  return scene;
}

template <typename F>
double seconds(F&& run) {
  const double t0 = thread_cpu_seconds();
  run();
  return thread_cpu_seconds() - t0;
}

double time_ours(const Scene& scene, int steps, bool solid) {
  WorldSpec spec;
  spec.arena = {scene.side, scene.side, Topology::Torus};
  spec.robots.count = static_cast<int>(scene.positions.size());
  spec.robots.radius = kRadius;
  spec.robots.detection_radius = kDetection;
  spec.robots.speed = kSpeed;
  spec.controller.type = "collision";
  spec.engine.type = EngineType::Box2D;
  spec.engine.dt = kDt;
  const std::size_t n = scene.positions.size();
  std::vector<MotionCommand> commands(n);
  for (std::size_t i = 0; i < n; ++i) {
    commands[i].velocity = scene.velocities[i];
    commands[i].blocked_by = solid ? ~SignalMask{0} : 0;
  }
  const std::vector<Signal> signals(n, 0);
  auto engine = make_box2d_engine(spec, scene.positions);
  for (int k = 0; k < kWarmup; ++k) engine->step(commands, signals);
  return seconds([&] {
    for (int k = 0; k < steps; ++k) engine->step(commands, signals);
  });
}

double time_bare(const Scene& scene, int steps, bool solid) {
  const auto n = scene.positions.size();
  {
    b2World world(b2Vec2(0.0f, 0.0f));
    world.SetAllowSleeping(false);
    world.SetContinuousPhysics(false);
    std::vector<b2Body*> bodies(n);
    for (std::size_t i = 0; i < n; ++i) {
      b2BodyDef def;
      def.type = b2_dynamicBody;
      def.position.Set(static_cast<float>(scene.positions[i].x),
                       static_cast<float>(scene.positions[i].y));
      def.fixedRotation = true;
      bodies[i] = world.CreateBody(&def);
      b2CircleShape disc;
      disc.m_radius = static_cast<float>(kRadius);
      b2FixtureDef fd;
      fd.shape = &disc;
      fd.density = 1.0f;
      fd.friction = 0.0f;
      fd.filter = box2d::filter_for(box2d::FixtureRole::Solid);
      if (!solid) fd.filter.maskBits = 0;  // GO agents pass over each other
      bodies[i]->CreateFixture(&fd);
      b2CircleShape sensor;
      sensor.m_radius = static_cast<float>(0.5 * kDetection);
      b2FixtureDef sd;
      sd.shape = &sensor;
      sd.isSensor = true;
      sd.filter = box2d::filter_for(box2d::FixtureRole::Detect);
      bodies[i]->CreateFixture(&sd);
    }
    auto step = [&] {
      for (std::size_t i = 0; i < n; ++i) {
        bodies[i]->SetLinearVelocity(b2Vec2(static_cast<float>(scene.velocities[i].x),
                                            static_cast<float>(scene.velocities[i].y)));
      }
      world.Step(static_cast<float>(kDt), 8, 3);
    };
    for (int k = 0; k < kWarmup; ++k) step();
    return seconds([&] {
      for (int k = 0; k < steps; ++k) step();
    });
  }
}

}  // namespace

Box2DBenchResult bench_box2d(int n, int steps, int repeats, bool solid) {
  const Scene scene = make_scene(n);
  // Half the arena's side of travel at most (see the header).
  const int longest = std::max(1, static_cast<int>(0.5 * scene.side / (kSpeed * kDt)) - kWarmup);
  steps = std::min(steps, longest);
  Box2DBenchResult result;
  result.n = n;
  result.steps = steps;
  // Interleaved, so that both loops see the same machine load; the best run of each counts.
  double bare = INFINITY;
  double ours = INFINITY;
  for (int r = 0; r < repeats; ++r) {
    bare = std::min(bare, time_bare(scene, steps, solid));
    ours = std::min(ours, time_ours(scene, steps, solid));
  }
  const double body_steps = static_cast<double>(n) * steps;
  result.bare_box2d_body_steps_per_s = body_steps / bare;
  result.body_steps_per_s = body_steps / ours;
  return result;
}

}  // namespace swarmagg
