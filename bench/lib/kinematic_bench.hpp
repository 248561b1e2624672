#pragma once
// Throughput of the kinematic engine with its controllers, as `swarmagg bench` reports it.
// Method: N agents at the paper's density (150 per 180 x 180, the square arena scaled with
// N), s = 4, r = 1, v = 1, dt = 0.1, one replicate on one thread unless asked otherwise.
// The replicates are built and warmed up outside the clock (the thread's CPU time with one
// thread, the wall clock with more); then the whole step (controller,
// engine, aggregates) is timed; the best of `repeats` runs is kept. Scenarios:
//  - the worst case, collision controller in ghost mode: every agent moves every step and
//    every encounter is resolved. Its statistics do not change with time, so one replicate
//    warms up for 20 steps and is timed for `budget / n` steps.
//  - Bayindir's full model with p = 0.001. Its cost changes as aggregates form, so every N
//    times the same window, steps 200 to 250 (t = 20 to 25, when the first aggregates
//    exist), over as many replicates as a third of the budget takes.
#include <cstdint>

#include "config/world_spec.hpp"

namespace swarmagg {

enum class BenchScenario { GhostWorstCase, BayindirFull };

struct KinematicBenchResult {
  int n = 0;
  std::int64_t warmup_steps = 0;
  std::int64_t steps = 0;  // timed, per replicate
  int replicates = 0;
  double agent_steps_per_s = 0.0;
  double real_time_factor = 0.0;  // simulated tu per wall-clock second
};

// The world the benchmark runs for n agents.
WorldSpec bench_world(int n, BenchScenario scenario);
// `budget`: agent-steps to time per repeat (about; see above).
KinematicBenchResult bench_kinematic(int n, BenchScenario scenario, double budget, int repeats = 3,
                                     int threads = 1);

// A world as it runs: its first replicate from t = 0 for budget / N steps (at least 10^4),
// whole steps timed on one thread, nothing warmed up (a paper Soysal world spends most of a
// run with its agents in aggregates at rest, which is what this measures).
KinematicBenchResult bench_world_run(const WorldSpec& spec, double budget);

}  // namespace swarmagg
