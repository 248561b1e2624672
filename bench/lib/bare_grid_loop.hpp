#pragma once
// The bare loop the kinematic engine's full model is measured against (`swarmagg bench`,
// kinematic_bare): N agents moving straight at constant velocity on a torus. Each step moves
// and wraps them, counting-sorts them into a grid of square cells at least as wide as the
// detection radius, and finds every pair within that radius by its minimum-image distance in
// the cells around each agent. No controller, no contacts, no observers, nothing kept from
// one step to the next: what any step of N agents that perceive each other has to do.
#include <cstdint>
#include <span>
#include <vector>

#include "bench/lib/kinematic_bench.hpp"
#include "core/vec2.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

class BareGridLoop {
 public:
  // `agents` placed uniformly at random (from `seed`) on a `side` x `side` torus, each heading
  // its own random way at `speed`.
  BareGridLoop(int agents, double side, double radius, double speed, double dt, std::uint64_t seed);

  // Moves every agent by one step and returns how many pairs lie within the radius then.
  std::uint64_t step();

  std::span<const Vec2> positions() const { return positions_; }
  const ArenaGeometry& arena() const { return arena_; }

 private:
  void sort_into_cells();
  std::uint64_t pairs_between(std::uint32_t cell, std::uint32_t other) const;
  std::uint64_t pairs_within(std::uint32_t cell) const;

  ArenaGeometry arena_;
  double radius2_;
  double dt_;
  std::uint32_t cells_per_side_;
  double cells_per_unit_;
  std::vector<Vec2> positions_;
  std::vector<Vec2> velocities_;
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> cell_start_;  // cells_per_side^2 + 1 entries
  std::vector<Vec2> sorted_;               // positions in cell order
};

// The bare loop at the paper's density (as bench_world), warmed up for 20 steps and timed
// for budget / n steps (at least 10) on the calling thread's CPU clock.
KinematicBenchResult bench_bare_grid_loop(int n, double budget);

}  // namespace swarmagg
