#pragma once
// Throughput of the kinematic engine with its controllers, as `swarmagg bench` reports it.
// Method: N agents at the paper's density (150 per 180 x 180, the square arena scaled with
// N), s = 4, r = 1, v = 1, dt = 0.1, one replicate on one thread unless asked otherwise.
// The replicate is built and warmed up for 20 steps outside the clock; then the whole step
// (controller, engine, aggregates) is timed over `steps` steps; the best of `repeats` runs
// is kept. Scenarios: the worst case (collision controller in ghost mode: every agent moves
// every step and every encounter is resolved) and Bayindir's full model with p = 0.001.
#include <cstdint>

#include "config/world_spec.hpp"

namespace swarmagg {

enum class BenchScenario { GhostWorstCase, BayindirFull };

struct KinematicBenchResult {
  int n = 0;
  std::int64_t steps = 0;
  double agent_steps_per_s = 0.0;
  double real_time_factor = 0.0;  // simulated tu per wall-clock second
};

// The world the benchmark runs for n agents.
WorldSpec bench_world(int n, BenchScenario scenario);
KinematicBenchResult bench_kinematic(int n, BenchScenario scenario, std::int64_t steps,
                                     int repeats = 3, int threads = 1);

}  // namespace swarmagg
