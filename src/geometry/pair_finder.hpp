#pragma once
// All pairs of points within a radius R of each other on an arena (torus-aware): the one
// spatial pair search of the code outside the kinematic engine's strips (which serve its hot
// path and fall back on this one). Points are bucketed into cells at least R wide (wider
// when the arena holds far more cells than points), so a point is compared only with the
// 3 x 3 cells around its own; an arena fewer than three cells across compares every pair.
// Buffers are kept from one use to the next: no allocation once warmed up.
#include <cstdint>
#include <vector>

#include "core/vec2.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

class PairFinder {
 public:
  // Starts over for points within `radius` of each other on `arena`, about `expected` of
  // them (which sizes the cells).
  void reset(const ArenaGeometry& arena, double radius, std::size_t expected);
  // Adds a point inside the arena (its edges included); points are numbered 0, 1, ...
  void add(Vec2 p);
  std::uint32_t size() const { return static_cast<std::uint32_t>(points_.size()); }

  // Calls visit(k, d) for every added point k within the radius of p, d the displacement
  // from p to point k (minimum image on a torus; norm2(d) <= radius^2).
  template <typename Visit>
  void for_each_near(Vec2 p, Visit&& visit) const;

  // Calls visit(i, j, d) once for every pair i < j of added points within the radius, d the
  // displacement from point i to point j. Pairs come by i; for one i, in no set order.
  template <typename Visit>
  void for_each_pair(Visit&& visit) const;

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  int column_of(double x) const;
  int row_of(double y) const;
  template <typename Visit>
  void visit_cell(int column, int row, Vec2 p, Visit& visit) const;

  ArenaGeometry arena_{1.0, 1.0, Topology::Torus};
  double radius2_ = 0.0;
  int columns_ = 1;
  int rows_ = 1;
  bool every_pair_ = true;  // fewer than three cells along an axis
  std::vector<Vec2> points_;
  std::vector<std::uint32_t> head_;  // per cell: the last point added to it
  std::vector<std::uint32_t> next_;  // per point: the point added to its cell before it
};

template <typename Visit>
void PairFinder::visit_cell(int column, int row, Vec2 p, Visit& visit) const {
  if (arena_.torus()) {
    column = (column + columns_) % columns_;
    row = (row + rows_) % rows_;
  } else if (column < 0 || column >= columns_ || row < 0 || row >= rows_) {
    return;
  }
  for (std::uint32_t k = head_[static_cast<std::size_t>(row) * columns_ + column]; k != kNone;
       k = next_[k]) {
    const Vec2 d = arena_.displacement(p, points_[k]);
    if (norm2(d) <= radius2_) visit(k, d);
  }
}

template <typename Visit>
void PairFinder::for_each_near(Vec2 p, Visit&& visit) const {
  if (every_pair_) {
    for (std::uint32_t k = 0; k < points_.size(); ++k) {
      const Vec2 d = arena_.displacement(p, points_[k]);
      if (norm2(d) <= radius2_) visit(k, d);
    }
    return;
  }
  const int column = column_of(p.x), row = row_of(p.y);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) visit_cell(column + dx, row + dy, p, visit);
  }
}

template <typename Visit>
void PairFinder::for_each_pair(Visit&& visit) const {
  for (std::uint32_t i = 0; i < points_.size(); ++i) {
    for_each_near(points_[i], [&](std::uint32_t j, Vec2 d) {
      if (j > i) visit(i, j, d);
    });
  }
}

}  // namespace swarmagg
