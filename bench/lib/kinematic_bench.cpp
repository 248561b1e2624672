#include "bench/lib/kinematic_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "bench/lib/paper_density_world.hpp"
#include "core/thread_clock.hpp"
#include "run/replicate.hpp"

namespace swarmagg {

WorldSpec bench_world(int n, BenchScenario scenario) {
  return paper_density_world(n,
                             scenario == BenchScenario::GhostWorstCase ? "collision" : "bayindir");
}

namespace {

struct BenchPlan {
  std::int64_t warmup_steps = 0;
  std::int64_t steps = 0;
  int replicates = 1;
};

BenchPlan plan_for(int n, BenchScenario scenario, double budget) {
  if (scenario == BenchScenario::GhostWorstCase) {
    return {20, std::max<std::int64_t>(10, std::llround(budget / n)), 1};
  }
  constexpr std::int64_t kWindow = 50;
  const double replicates = std::round(budget / 3.0 / (static_cast<double>(n) * kWindow));
  return {200, kWindow, static_cast<int>(std::max(1.0, replicates))};
}

// One thread is timed by its own CPU time, so that other processes on the machine do not
// count; several threads by the wall clock.
double now(int threads) {
  if (threads == 1) return thread_cpu_seconds();
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

KinematicBenchResult bench_kinematic(int n, BenchScenario scenario, double budget, int repeats,
                                     int threads) {
  const WorldSpec spec = bench_world(n, scenario);
  const BenchPlan plan = plan_for(n, scenario, budget);
  double best = 0.0;
  for (int r = 0; r < repeats; ++r) {
    double seconds = 0.0;
    for (int k = 0; k < plan.replicates; ++k) {
      Replicate replicate(spec, r * plan.replicates + k);
      replicate.set_threads(threads);
      for (std::int64_t step = 0; step < plan.warmup_steps; ++step) replicate.step();
      const double start = now(threads);
      for (std::int64_t step = 0; step < plan.steps; ++step) replicate.step();
      seconds += now(threads) - start;
    }
    const double agent_steps =
        static_cast<double>(n) * static_cast<double>(plan.steps) * plan.replicates;
    best = std::max(best, agent_steps / seconds);
  }
  return {n, plan.warmup_steps, plan.steps, plan.replicates, best, best / n * spec.engine.dt};
}

KinematicBenchResult bench_world_run(const WorldSpec& spec, double budget) {
  const int n = spec.robots.count;
  const std::int64_t steps = std::max<std::int64_t>(10000, std::llround(budget / n));
  Replicate replicate(spec, 0);
  const double start = thread_cpu_seconds();
  for (std::int64_t step = 0; step < steps; ++step) replicate.step();
  const double seconds = thread_cpu_seconds() - start;
  const double rate = static_cast<double>(n) * static_cast<double>(steps) / seconds;
  return {n, 0, steps, 1, rate, rate / n * spec.engine.dt};
}

}  // namespace swarmagg
