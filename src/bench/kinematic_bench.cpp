#include "bench/kinematic_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "config/world_loader.hpp"
#include "run/replicate.hpp"

namespace swarmagg {

WorldSpec bench_world(int n, BenchScenario scenario) {
  WorldSpec spec;
  spec.name = "bench";
  spec.source = "bench";
  const double side = 180.0 * std::sqrt(n / 150.0);
  spec.arena = {side, side, Topology::Torus};
  spec.robots.count = n;
  if (scenario == BenchScenario::GhostWorstCase) {
    spec.controller.type = ControllerType::Collision;
    spec.controller.collision_mode = CollisionMode::Ghost;
  } else {
    spec.controller.type = ControllerType::Bayindir;
    spec.controller.p_leave = 0.001;
  }
  spec.run.replicates = 1;
  check_world(spec);
  return spec;
}

KinematicBenchResult bench_kinematic(int n, BenchScenario scenario, std::int64_t steps,
                                     int repeats, int threads) {
  const WorldSpec spec = bench_world(n, scenario);
  double best = 0.0;
  for (int r = 0; r < repeats; ++r) {
    Replicate replicate(spec, r);
    replicate.set_threads(threads);
    for (int k = 0; k < 20; ++k) replicate.step();
    const auto start = std::chrono::steady_clock::now();
    for (std::int64_t k = 0; k < steps; ++k) replicate.step();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, static_cast<double>(n) * static_cast<double>(steps) / seconds);
  }
  return {n, steps, best, best / n * spec.engine.dt};
}

}  // namespace swarmagg
