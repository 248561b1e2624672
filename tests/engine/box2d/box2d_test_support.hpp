#pragma once
// Helpers shared by the Box2D engine tests: small worlds built in code, random non-overlapping
// placements, and runs that feed the same MotionCommand to every step.
#include <cmath>
#include <memory>
#include <random>
#include <span>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/motion_command.hpp"
#include "core/vec2.hpp"
#include "engine/box2d/box2d_engine.hpp"
#include "engine/engine.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg::testing {

constexpr Signal kGo = 0;
constexpr Signal kWait = 1;
constexpr Signal kLeave = 2;
constexpr SignalMask kAll = ~SignalMask{0};
constexpr double kPi = 3.141592653589793;

inline WorldSpec box2d_world(double width, double height, int count,
                             Topology topology = Topology::Torus) {
  WorldSpec spec;
  spec.name = "box2d-test";
  spec.arena = {width, height, topology};
  spec.robots.count = count;
  spec.robots.radius = 1.0;
  spec.robots.detection_radius = 4.0;
  spec.robots.speed = 1.0;
  spec.controller.type = "collision";
  spec.engine.type = EngineType::Box2D;
  spec.engine.dt = 0.1;
  return spec;
}

// Uniform positions at least `min_distance` apart (minimum image on a torus).
inline std::vector<Vec2> random_positions(const WorldSpec& spec, int count, double min_distance,
                                          std::uint64_t seed, double border = 0.0) {
  std::mt19937_64 rng(seed);
  const ArenaGeometry geometry = spec.arena.geometry();
  std::uniform_real_distribution<double> ux(border, spec.arena.width - border);
  std::uniform_real_distribution<double> uy(border, spec.arena.height - border);
  std::vector<Vec2> out;
  while (static_cast<int>(out.size()) < count) {
    const Vec2 p{ux(rng), uy(rng)};
    bool ok = true;
    for (const Vec2& q : out) ok = ok && geometry.distance(p, q) >= min_distance;
    if (ok) out.push_back(p);
  }
  return out;
}

inline std::vector<Vec2> random_headings(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  std::vector<Vec2> out;
  for (int i = 0; i < count; ++i) out.push_back(from_angle(angle(rng)));
  return out;
}

// Minimum-image distance of every pair, smallest first.
inline double smallest_distance(const ArenaGeometry& geometry, std::span<const Vec2> p) {
  double smallest = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      smallest = std::min(smallest, geometry.distance(p[i], p[j]));
    }
  }
  return smallest;
}

}  // namespace swarmagg::testing
