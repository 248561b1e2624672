#include "geometry/pair_finder.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

// Cells per point at most: more cells than this cost more to clear than they save.
constexpr double kCellsPerPoint = 4.0;

}  // namespace

void PairFinder::reset(const ArenaGeometry& arena, double radius, std::size_t expected) {
  arena_ = arena;
  radius2_ = radius * radius;
  const double max_cells = std::max(16.0, kCellsPerPoint * static_cast<double>(expected));
  const double side = std::max(radius, std::sqrt(arena.width() * arena.height() / max_cells));
  const auto cells_along = [side](double length) {
    return static_cast<int>(std::clamp(std::floor(length / side), 1.0, 1048576.0));
  };
  columns_ = cells_along(arena.width());
  rows_ = cells_along(arena.height());
  every_pair_ = columns_ < 3 || rows_ < 3;
  points_.clear();
  next_.clear();
  head_.assign(every_pair_ ? 0 : static_cast<std::size_t>(columns_) * rows_, kNone);
}

int PairFinder::column_of(double x) const {
  return std::clamp(static_cast<int>(x / arena_.width() * columns_), 0, columns_ - 1);
}

int PairFinder::row_of(double y) const {
  return std::clamp(static_cast<int>(y / arena_.height() * rows_), 0, rows_ - 1);
}

void PairFinder::add(Vec2 p) {
  const auto k = static_cast<std::uint32_t>(points_.size());
  points_.push_back(p);
  if (every_pair_) return;
  const std::size_t cell = static_cast<std::size_t>(row_of(p.y)) * columns_ + column_of(p.x);
  next_.push_back(head_[cell]);
  head_[cell] = k;
}

}  // namespace swarmagg
