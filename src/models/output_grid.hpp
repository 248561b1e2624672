#pragma once
// The steps at which models report. The Bayindir model reports on the simulation's record
// grid (every run.record_every steps), so its rows line up with timeseries.csv. The
// partition model costs per reported step, so it reports at a modest number of steps,
// log-spaced (early transient) and evenly spaced (late approach), rounded to the record grid.
#include <cstdint>
#include <functional>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

// 0, k, 2k, ... and world.steps(), k = run.record_every: the steps a run records.
std::vector<std::int64_t> record_grid(const WorldSpec& world);

// 0 plus about `points` log-spaced and `points` evenly spaced steps in (0, world.steps()],
// rounded to multiples of run.record_every, sorted, without duplicates.
std::vector<std::int64_t> sparse_grid(const WorldSpec& world, int points);

// 0, 1 and about `points` log-spaced and `points` evenly spaced whole steps up to
// world.steps(), whatever run.record_every is: the steps over which a model's run average
// is integrated, so that the average does not depend on how often the run records.
std::vector<std::int64_t> integration_grid(const WorldSpec& world, int points);

// Told how many more model steps a walk has taken, every kWalkProgressBatch steps and at its
// end: the caller's progress line and its check for Ctrl-C (which throws out of the walk).
using WalkProgress = std::function<void(std::int64_t steps)>;
inline constexpr std::int64_t kWalkProgressBatch = 4096;

// Steps the model from 0 to grid.back(): at each step, calls record(step) when the step is
// on the grid, then advance(step) unless it is the last.
template <typename Advance, typename Record>
void walk_grid(const std::vector<std::int64_t>& grid, Advance&& advance, Record&& record,
               const WalkProgress& progress = {}) {
  std::size_t next = 0;
  std::int64_t unreported = 0;
  for (std::int64_t step = 0; next < grid.size(); ++step) {
    if (step == grid[next]) {
      record(step);
      ++next;
    }
    if (next == grid.size()) break;
    advance(step);
    if (progress && ++unreported == kWalkProgressBatch) {
      progress(unreported);
      unreported = 0;
    }
  }
  if (progress && unreported > 0) progress(unreported);
}

}  // namespace swarmagg
