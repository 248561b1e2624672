#include "plot/drawn_points.hpp"

#include <algorithm>

#include "core/errors.hpp"
#include "models/output_grid.hpp"

namespace swarmagg {

namespace {

// Every `stride`-th of `count` points from the first, and the last.
std::size_t points_drawn(std::size_t count, std::size_t stride) {
  const std::size_t last = count - 1;
  return last / stride + 1 + (last % stride != 0 ? 1 : 0);
}

}  // namespace

std::vector<std::size_t> drawn_indices(std::size_t count) {
  std::vector<std::size_t> indices;
  if (count == 0) return indices;
  std::size_t stride = 1;
  while (points_drawn(count, stride) > kMostDrawnPoints) ++stride;
  for (std::size_t i = 0; i < count; i += stride) indices.push_back(i);
  if (indices.back() != count - 1) indices.push_back(count - 1);
  return indices;
}

StepFilter drawn_steps(const WorldSpec& world) {
  const std::vector<std::int64_t> grid = record_grid(world);
  if (grid.size() <= kMostDrawnPoints) return {};
  std::vector<std::int64_t> drawn;
  for (const std::size_t i : drawn_indices(grid.size())) drawn.push_back(grid[i]);
  return [drawn = std::move(drawn)](std::int64_t step) {
    return std::binary_search(drawn.begin(), drawn.end(), step);
  };
}

std::vector<StepSeries> read_drawn_series(const RunFiles& run,
                                          const std::vector<std::string>& columns) {
  std::vector<StepSeries> series =
      read_step_series(run.timeseries, columns, drawn_steps(run.world));
  if (series.front().steps.empty())
    throw InputError(run.timeseries.string() + ": holds no recorded step of its run");
  return series;
}

}  // namespace swarmagg
