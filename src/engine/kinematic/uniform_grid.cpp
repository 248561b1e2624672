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
  arena_ = arena;
  nx_ = cells_along(arena.width(), min_cell);
  ny_ = cells_along(arena.height(), min_cell);
  const double per_x = nx_ / arena.width();
  const double per_y = ny_ / arena.height();
  const std::size_t n = positions.size();
  cell_of_.resize(n);
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int x = std::clamp(static_cast<int>(positions[i].x * per_x), 0, nx_ - 1);
    const int y = std::clamp(static_cast<int>(positions[i].y * per_y), 0, ny_ - 1);
    cell_of_[i] = static_cast<std::uint32_t>(y * nx_ + x);
    ++cell_start_[cell_of_[i] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  // Agents stay in index order within a cell, which keeps every later loop deterministic.
  cursor_.assign(cell_start_.begin(), cell_start_.end() - 1);
  sorted_id_.resize(n);
  sorted_position_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t slot = cursor_[cell_of_[i]]++;
    sorted_id_[slot] = static_cast<std::uint32_t>(i);
    sorted_position_[slot] = positions[i];
  }
}

}  // namespace swarmagg
