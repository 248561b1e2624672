#include "models/output_grid.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {

std::vector<std::int64_t> record_grid(const WorldSpec& world) {
  const std::int64_t every = std::max(1, world.run.record_every);
  std::vector<std::int64_t> grid;
  for (std::int64_t step = 0; step <= world.steps(); step += every) grid.push_back(step);
  if (grid.back() != world.steps()) grid.push_back(world.steps());
  return grid;
}

std::vector<std::int64_t> sparse_grid(const WorldSpec& world, int points) {
  const std::int64_t last = world.steps();
  const std::int64_t every = std::max(1, world.run.record_every);
  auto on_record_grid = [&](double step) {
    const auto rounded = every * std::llround(step / static_cast<double>(every));
    return std::clamp<std::int64_t>(rounded, std::min(every, last), last);
  };
  std::vector<std::int64_t> grid{0};
  if (last > 0) {
    const double log_last = std::log(static_cast<double>(last));
    for (int i = 1; i <= points; ++i) {
      grid.push_back(on_record_grid(std::exp(log_last * i / points)));
      grid.push_back(on_record_grid(static_cast<double>(last) * i / points));
    }
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

std::vector<std::int64_t> integration_grid(const WorldSpec& world, int points) {
  const std::int64_t last = world.steps();
  std::vector<std::int64_t> grid{0};
  if (last > 0) {
    const double log_last = std::log(static_cast<double>(last));
    for (int i = 0; i <= points; ++i) {
      grid.push_back(std::llround(std::exp(log_last * i / points)));
      grid.push_back(std::llround(static_cast<double>(last) * i / points));
    }
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

}  // namespace swarmagg
