#pragma once
// How a pair of nearby agents is reported, whatever structure found it. The reference is a
// uniform grid of cells at least `min_cell` wide, scanned cell by cell in row-major order
// over a half shell (the cell itself, then east, north-west, north, north-east):
//  - the agent of the scanning cell is `a`, the other `b`; the offset is
//    (p_b + seam shift) - p_a, so across a torus seam its rounding depends on which agent
//    the grid calls `a`;
//  - pairs rank by (cell of a, shell slot, id of a, id of b), the order the scan met them.
// The guarded-motion solver breaks ties between simultaneous events by this rank, so
// keeping the convention fixed keeps results bit-identical however pairs are searched.
#include <algorithm>
#include <cstdint>
#include <optional>

#include "core/vec2.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

// A pair as the reference grid reports it: i < j, offset from i to j, |offset|^2 = d2.
struct ConventionalPair {
  std::uint32_t i = 0;
  std::uint32_t j = 0;
  Vec2 offset;
  double d2 = 0.0;
  std::uint32_t rank = 0;  // cell of a * 5 + shell slot
  bool a_is_j = false;     // the grid's `a` is j (ids break rank ties as (a, b))
};

class PairConvention {
 public:
  PairConvention() = default;
  PairConvention(const ArenaGeometry& arena, double min_cell)
      : arena_(arena),
        nx_(cells_along(arena.width(), min_cell)),
        ny_(cells_along(arena.height(), min_cell)),
        per_x_(nx_ / arena.width()),
        per_y_(ny_ / arena.height()) {}

  static int cells_along(double length, double min_cell) {
    return std::max(1, static_cast<int>(std::floor(length / min_cell)));
  }

  int columns() const { return nx_; }
  int rows() const { return ny_; }
  // The grid scans all pairs directly below three cells along an axis (uniform_grid.hpp).
  bool scans_all_pairs() const { return nx_ < 3 || ny_ < 3; }
  int row_of(double y) const { return std::clamp(static_cast<int>(y * per_y_), 0, ny_ - 1); }
  int column_of(double x) const { return std::clamp(static_cast<int>(x * per_x_), 0, nx_ - 1); }

  // The pair of agents `id_p` at p and `id_q` at q as the grid reports it, if the grid
  // visits it and its squared distance is within reach2.
  std::optional<ConventionalPair> report(std::uint32_t id_p, Vec2 p, std::uint32_t id_q, Vec2 q,
                                         double reach2) const;

 private:
  // Shell slot of the cell (dx, dy) columns/rows away from the scanning cell.
  static int shell_slot(int dx, int dy) { return dy == 0 ? 1 : dx + 3; }
  bool east_of(int from, int to) const {  // `to` is the next column after `from`
    return to == from + 1 || (arena_.torus() && from == nx_ - 1 && to == 0);
  }
  bool below(int from, int to) const {  // `to` is the next row after `from`
    return to == from + 1 || (arena_.torus() && from == ny_ - 1 && to == 0);
  }
  // Column step from `from` to `to` among -1, 0, 1 (torus-aware), or 2 when not adjacent.
  int column_step(int from, int to) const;

  ArenaGeometry arena_{1.0, 1.0, Topology::Torus};
  int nx_ = 1;
  int ny_ = 1;
  double per_x_ = 1.0;
  double per_y_ = 1.0;
};

inline int PairConvention::column_step(int from, int to) const {
  if (to == from) return 0;
  if (east_of(from, to)) return 1;
  if (east_of(to, from)) return -1;
  return 2;
}

inline std::optional<ConventionalPair> PairConvention::report(std::uint32_t id_p, Vec2 p,
                                                              std::uint32_t id_q, Vec2 q,
                                                              double reach2) const {
  int row_p = row_of(p.y), row_q = row_of(q.y);
  int column_p = column_of(p.x), column_q = column_of(q.x);
  // Orient so that p is the grid's `a`: the scanning cell comes first in the half shell.
  bool swap = false;
  if (row_p == row_q) {
    if (column_p == column_q) {
      swap = id_q < id_p;  // one cell: the scan meets its agents in index order
    } else if (!east_of(column_p, column_q)) {
      if (!east_of(column_q, column_p)) return std::nullopt;
      swap = true;
    }
  } else if (!below(row_p, row_q)) {
    if (!below(row_q, row_p)) return std::nullopt;
    swap = true;
  }
  if (swap) {
    std::swap(id_p, id_q);
    std::swap(p, q);
    std::swap(row_p, row_q);
    std::swap(column_p, column_q);
  }
  const int dx = column_step(column_p, column_q);
  if (dx == 2) return std::nullopt;
  const int dy = row_q == row_p ? 0 : 1;
  const int slot = dx == 0 && dy == 0 ? 0 : shell_slot(dx, dy);
  Vec2 shift{};
  if (column_p + dx < 0) shift.x = -arena_.width();
  if (column_p + dx >= nx_) shift.x = arena_.width();
  if (row_p + dy >= ny_) shift.y = arena_.height();
  Vec2 d = q + shift - p;
  const double d2 = norm2(d);
  if (d2 > reach2) return std::nullopt;
  ConventionalPair pair{
      id_p, id_q, d, d2, static_cast<std::uint32_t>((row_p * nx_ + column_p) * 5 + slot), false};
  if (id_p > id_q) {
    std::swap(pair.i, pair.j);
    pair.offset = -d;
    pair.a_is_j = true;
  }
  return pair;
}

}  // namespace swarmagg
