#pragma once
// Distances and wrapping in the arena: the one home of the torus's minimum image. On a torus
// every displacement is the shortest of the periodic copies; with walls it is the plain
// difference. Below config (whose ArenaSpec makes one), engines, observers and render.
#include <algorithm>
#include <cmath>

#include "core/vec2.hpp"

namespace swarmagg {

enum class Topology { Torus, Walls };

class ArenaGeometry {
 public:
  ArenaGeometry(double width, double height, Topology topology)
      : width_(width), height_(height), torus_(topology == Topology::Torus) {}

  double width() const { return width_; }
  double height() const { return height_; }
  bool torus() const { return torus_; }

  // The displacement from `from` to `to`.
  Vec2 displacement(Vec2 from, Vec2 to) const {
    Vec2 d = to - from;
    if (torus_) {
      d.x = minimum_image(d.x, width_);
      d.y = minimum_image(d.y, height_);
    }
    return d;
  }
  double distance(Vec2 a, Vec2 b) const { return norm(displacement(a, b)); }

  // On a torus, the same point expressed inside [0, width) x [0, height).
  Vec2 wrap(Vec2 p) const {
    if (!torus_) return p;
    return {wrap_coordinate(p.x, width_), wrap_coordinate(p.y, height_)};
  }

  // The longest move of a body in one step that the engines resolve: a quarter of the shorter
  // side, and on a torus less, as events within a step are found from each pair's nearest
  // image at its start. Two bodies moving apart by twice this must stay farther than `radius`
  // (the largest radius events happen at) from each other's far image: L/4 - radius/2.
  double longest_move(double radius) const {
    const double quarter = 0.25 * std::min(width_, height_);
    return torus_ ? quarter - 0.5 * radius : quarter;
  }

  // The shortest move a world may ask for (robots.speed * engine.dt): 10^-12 of the longer
  // side, some 4,500 ulps of a coordinate at the far edge, so that a step's move is never lost
  // in the rounding of positions.
  double position_resolution() const { return 1e-12 * std::max(width_, height_); }

  static double minimum_image(double d, double length) {
    if (d > 0.5 * length) return d - length;
    if (d < -0.5 * length) return d + length;
    return d;
  }
  static double wrap_coordinate(double x, double length) {
    if (x >= 0.0 && x < length) return x;
    double w = std::fmod(x, length);
    if (w < 0.0) w += length;
    // fmod of a tiny negative number plus length can round up to length itself.
    return w >= length ? 0.0 : w;
  }

 private:
  double width_;
  double height_;
  bool torus_;
};

}  // namespace swarmagg
