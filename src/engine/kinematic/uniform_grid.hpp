#pragma once
// A uniform grid over the arena, rebuilt by counting sort each step (O(N), no allocation
// after warm-up). Cells are at least `min_cell` wide, so every pair of agents closer than
// that lies in the same or adjacent cells.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec2.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

class UniformGrid {
 public:
  void rebuild(const ArenaGeometry& arena, double min_cell, std::span<const Vec2> positions);

  // Too few cells along an axis for the 3x3 neighbourhood to be distinct cells.
  bool degenerate() const { return nx_ < 3 || ny_ < 3; }

  // Calls visit(j) for every agent j in the 3x3 block of cells around agent i's cell
  // (including i itself). Callers filter by distance.
  template <typename Visit>
  void for_each_nearby(std::uint32_t i, Visit&& visit) const {
    const int cx = cell_x_[i];
    const int cy = cell_y_[i];
    for (int dy = -1; dy <= 1; ++dy) {
      int y = cy + dy;
      if (!wrap_axis(y, ny_)) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        int x = cx + dx;
        if (!wrap_axis(x, nx_)) continue;
        const std::size_t cell = static_cast<std::size_t>(y) * nx_ + x;
        for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) visit(sorted_[k]);
      }
    }
  }

 private:
  bool wrap_axis(int& c, int n) const {
    if (c >= 0 && c < n) return true;
    if (!torus_) return false;
    c = (c + n) % n;
    return true;
  }

  bool torus_ = true;
  int nx_ = 1;
  int ny_ = 1;
  std::vector<std::int32_t> cell_x_;
  std::vector<std::int32_t> cell_y_;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> cursor_;
  std::vector<std::uint32_t> sorted_;
};

}  // namespace swarmagg
