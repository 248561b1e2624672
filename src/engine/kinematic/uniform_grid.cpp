#include "engine/kinematic/uniform_grid.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

int cells_along(double length, double min_cell) {
  return std::max(1, static_cast<int>(std::floor(length / min_cell)));
}

}  // namespace

void UniformGrid::rebuild(const ArenaGeometry& arena, double min_cell,
                          std::span<const Vec2> positions) {
  torus_ = arena.torus();
  nx_ = cells_along(arena.width(), min_cell);
  ny_ = cells_along(arena.height(), min_cell);
  const double inv_w = nx_ / arena.width();
  const double inv_h = ny_ / arena.height();
  const std::size_t n = positions.size();
  cell_x_.resize(n);
  cell_y_.resize(n);
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  sorted_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    cell_x_[i] = std::clamp(static_cast<int>(positions[i].x * inv_w), 0, nx_ - 1);
    cell_y_[i] = std::clamp(static_cast<int>(positions[i].y * inv_h), 0, ny_ - 1);
    ++cell_start_[static_cast<std::size_t>(cell_y_[i]) * nx_ + cell_x_[i] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  // Agents stay in index order within a cell, which keeps every later loop deterministic.
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t cell = static_cast<std::size_t>(cell_y_[i]) * nx_ + cell_x_[i];
    sorted_[cursor_[cell]++] = static_cast<std::uint32_t>(i);
  }
}

}  // namespace swarmagg
