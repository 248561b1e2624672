#include "bench/lib/bare_grid_loop.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "core/thread_clock.hpp"

namespace swarmagg {

BareGridLoop::BareGridLoop(int agents, double side, double radius, double speed, double dt,
                           std::uint64_t seed)
    : arena_(side, side, Topology::Torus),
      radius2_(radius * radius),
      dt_(dt),
      // At least three cells a side, so that the cells around one are all different.
      cells_per_side_(std::max(3u, static_cast<std::uint32_t>(side / radius))),
      cells_per_unit_(cells_per_side_ / side) {
  const CounterRng rng(seed);
  constexpr double kTwoPi = 6.283185307179586;
  const auto n = static_cast<std::uint32_t>(agents);
  for (std::uint32_t a = 0; a < n; ++a) {
    positions_.push_back({side * rng.uniform(0, a, Draw::Placement, 0),
                          side * rng.uniform(0, a, Draw::Placement, 1)});
    velocities_.push_back(from_angle(kTwoPi * rng.uniform(0, a, Draw::Heading)) * speed);
  }
  cell_of_.resize(n);
  cell_start_.resize(std::size_t{cells_per_side_} * cells_per_side_ + 1);
  sorted_.resize(n);
}

// A counting sort of the agents by cell: their positions, in cell order, lie in sorted_.
void BareGridLoop::sort_into_cells() {
  std::fill(cell_start_.begin(), cell_start_.end(), 0u);
  const std::uint32_t last = cells_per_side_ - 1;
  for (std::size_t a = 0; a < positions_.size(); ++a) {
    const auto cx = std::min(last, static_cast<std::uint32_t>(positions_[a].x * cells_per_unit_));
    const auto cy = std::min(last, static_cast<std::uint32_t>(positions_[a].y * cells_per_unit_));
    cell_of_[a] = cy * cells_per_side_ + cx;
    ++cell_start_[cell_of_[a] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  for (std::size_t a = 0; a < positions_.size(); ++a)
    sorted_[cell_start_[cell_of_[a]]++] = positions_[a];
  // Placing advanced each cell's start to the next one's: shift them back.
  for (std::size_t c = cell_start_.size() - 1; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

std::uint64_t BareGridLoop::pairs_between(std::uint32_t cell, std::uint32_t other) const {
  std::uint64_t pairs = 0;
  for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    for (std::uint32_t m = cell_start_[other]; m < cell_start_[other + 1]; ++m) {
      pairs += static_cast<std::uint64_t>(norm2(arena_.displacement(sorted_[k], sorted_[m])) <=
                                          radius2_);
    }
  }
  return pairs;
}

std::uint64_t BareGridLoop::pairs_within(std::uint32_t cell) const {
  std::uint64_t pairs = 0;
  for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) {
    for (std::uint32_t m = k + 1; m < cell_start_[cell + 1]; ++m) {
      pairs += static_cast<std::uint64_t>(norm2(arena_.displacement(sorted_[k], sorted_[m])) <=
                                          radius2_);
    }
  }
  return pairs;
}

// Each pair of neighbouring cells once: a cell with itself and with the four cells after it
// (right, and the three above), wrapped on the torus.
std::uint64_t BareGridLoop::step() {
  for (std::size_t a = 0; a < positions_.size(); ++a) {
    positions_[a] = arena_.wrap(positions_[a] + velocities_[a] * dt_);
  }
  sort_into_cells();
  const std::uint32_t side = cells_per_side_;
  std::uint64_t pairs = 0;
  for (std::uint32_t cy = 0; cy < side; ++cy) {
    const std::uint32_t up = (cy + 1) % side;
    for (std::uint32_t cx = 0; cx < side; ++cx) {
      const std::uint32_t left = (cx + side - 1) % side, right = (cx + 1) % side;
      const std::uint32_t cell = cy * side + cx;
      pairs += pairs_within(cell);
      pairs += pairs_between(cell, cy * side + right);
      pairs += pairs_between(cell, up * side + left);
      pairs += pairs_between(cell, up * side + cx);
      pairs += pairs_between(cell, up * side + right);
    }
  }
  return pairs;
}

KinematicBenchResult bench_bare_grid_loop(int n, double budget) {
  const WorldSpec spec = bench_world(n, BenchScenario::GhostWorstCase);
  BareGridLoop loop(n, spec.arena.width, spec.robots.detection_radius, spec.robots.speed,
                    spec.engine.dt, spec.run.seed);
  constexpr std::int64_t kWarmup = 20;
  const std::int64_t steps = std::max<std::int64_t>(10, std::llround(budget / n));
  std::uint64_t pairs = 0;
  for (std::int64_t s = 0; s < kWarmup; ++s) pairs += loop.step();
  const double start = thread_cpu_seconds();
  for (std::int64_t s = 0; s < steps; ++s) pairs += loop.step();
  const double seconds = thread_cpu_seconds() - start;
  // The pairs found are used, so that no compiler drops the search.
  if (pairs == ~std::uint64_t{0}) return {};
  const double rate = static_cast<double>(n) * static_cast<double>(steps) / seconds;
  return {n, kWarmup, steps, 1, rate, rate / n * spec.engine.dt};
}

}  // namespace swarmagg
