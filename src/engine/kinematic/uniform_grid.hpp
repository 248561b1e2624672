#pragma once
// A uniform grid over the arena, rebuilt by counting sort each step (O(N), no allocation
// after warm-up). Cells are at least `min_cell` wide, so every pair closer than that lies
// in the same or adjacent cells. Positions are copied in cell order, so the pair search
// reads memory sequentially, and each pair is visited once (a half shell of neighbouring
// cells), with the torus wrap applied as a whole-arena shift of the neighbouring cell.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec2.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

class UniformGrid {
 public:
  void rebuild(const ArenaGeometry& arena, double min_cell, std::span<const Vec2> positions);

  // Calls visit(i, j, d, d2) once for every unordered pair of agents with i < j whose
  // displacement d from i to j (minimum image on a torus) has |d|^2 = d2 <= reach^2.
  // `reach` must not exceed the min_cell of the last rebuild. Pairs come in cell order.
  template <typename Visit>
  void for_each_close_pair(double reach, Visit&& visit) const;

 private:
  template <typename Visit>
  void scan_all_pairs(double reach2, Visit& visit) const;
  bool neighbour_cell(int& x, int& y, Vec2& shift) const;

  ArenaGeometry arena_{1.0, 1.0, Topology::Torus};
  int nx_ = 1;
  int ny_ = 1;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> cursor_;
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> sorted_id_;
  std::vector<Vec2> sorted_position_;
};

inline bool UniformGrid::neighbour_cell(int& x, int& y, Vec2& shift) const {
  if (x < 0 || x >= nx_) {
    if (!arena_.torus()) return false;
    shift.x = x < 0 ? -arena_.width() : arena_.width();
    x = x < 0 ? x + nx_ : x - nx_;
  }
  if (y >= ny_) {
    if (!arena_.torus()) return false;
    shift.y = arena_.height();
    y -= ny_;
  }
  return true;
}

template <typename Visit>
void UniformGrid::scan_all_pairs(double reach2, Visit& visit) const {
  const std::size_t n = sorted_id_.size();
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      std::uint32_t i = sorted_id_[a], j = sorted_id_[b];
      Vec2 d = arena_.displacement(sorted_position_[a], sorted_position_[b]);
      if (i > j) {
        std::swap(i, j);
        d = -d;
      }
      const double d2 = norm2(d);
      if (d2 <= reach2) visit(i, j, d, d2);
    }
  }
}

template <typename Visit>
void UniformGrid::for_each_close_pair(double reach, Visit&& visit) const {
  const double reach2 = reach * reach;
  // With fewer than three cells along an axis the half shell would meet a cell twice.
  if (nx_ < 3 || ny_ < 3) return scan_all_pairs(reach2, visit);
  // The half shell: this cell, east, and the three cells of the row above.
  constexpr int kShell[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  for (int cy = 0; cy < ny_; ++cy) {
    for (int cx = 0; cx < nx_; ++cx) {
      const std::size_t cell = static_cast<std::size_t>(cy) * nx_ + cx;
      const std::uint32_t begin = cell_start_[cell], end = cell_start_[cell + 1];
      if (begin == end) continue;
      auto consider = [&](std::uint32_t a, std::uint32_t b, Vec2 shift) {
        Vec2 d = sorted_position_[b] + shift - sorted_position_[a];
        const double d2 = norm2(d);
        if (d2 > reach2) return;
        std::uint32_t i = sorted_id_[a], j = sorted_id_[b];
        if (i > j) {
          std::swap(i, j);
          d = -d;
        }
        visit(i, j, d, d2);
      };
      for (std::uint32_t a = begin; a < end; ++a) {
        for (std::uint32_t b = a + 1; b < end; ++b) consider(a, b, Vec2{});
      }
      for (const auto& offset : kShell) {
        int x = cx + offset[0], y = cy + offset[1];
        Vec2 shift{};
        if (!neighbour_cell(x, y, shift)) continue;
        const std::size_t other = static_cast<std::size_t>(y) * nx_ + x;
        const std::uint32_t other_begin = cell_start_[other], other_end = cell_start_[other + 1];
        for (std::uint32_t a = begin; a < end; ++a) {
          for (std::uint32_t b = other_begin; b < other_end; ++b) consider(a, b, shift);
        }
      }
    }
  }
}

}  // namespace swarmagg
