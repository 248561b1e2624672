// Soak test (issue 10; a benchmark, not CI): one replicate of a full-model world driven for
// 10^7 steps with every invariant (run/invariants.hpp) checked after every step, step to
// step included. Reports progress every 10^6 steps, then steps, wall time, throughput and
// the violation if one occurred (exit 1).
//
//   bench_soak [WORLD.yaml] [--steps N] [--set key.path=value ...]
//
// Default: worlds/paper/full-0.0025.yaml (N = 120, p = 0.0025) for 10^7 steps. Run it from
// a Release build on a quiet machine; compare `--set engine.type=box2d` the same way.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "config/world_keys.hpp"
#include "config/world_loader.hpp"
#include "run/invariants.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

using Clock = std::chrono::steady_clock;

struct SoakOptions {
  std::string world = SWARMAGG_SOURCE_DIR "/worlds/paper/full-0.0025.yaml";
  std::int64_t steps = 10'000'000;
  std::vector<std::string> overrides;
};

SoakOptions parse(int argc, char** argv) {
  SoakOptions options;
  for (int k = 1; k < argc; ++k) {
    const std::string argument = argv[k];
    if (argument == "--steps" && k + 1 < argc) {
      options.steps = std::atoll(argv[++k]);
    } else if (argument == "--set" && k + 1 < argc) {
      options.overrides.push_back(argv[++k]);
    } else if (argument.rfind("--", 0) != 0) {
      options.world = argument;
    } else {
      std::fprintf(stderr, "usage: bench_soak [WORLD.yaml] [--steps N] [--set key=value ...]\n");
      std::exit(2);
    }
  }
  return options;
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void report(const Replicate& r, Clock::time_point start) {
  const EventCounts& e = r.events();
  const double elapsed = seconds_since(start);
  std::printf(
      "%11lld steps  %8.1f s  %9.0f steps/s  NOA %3d  largest %3d  events C %llu G %llu "
      "D %llu S %llu\n",
      static_cast<long long>(r.steps_done()), elapsed,
      static_cast<double>(r.steps_done()) / elapsed, r.aggregates().count(),
      r.aggregates().largest(), static_cast<unsigned long long>(e.creations),
      static_cast<unsigned long long>(e.growths), static_cast<unsigned long long>(e.dissipations),
      static_cast<unsigned long long>(e.shrinks));
  std::fflush(stdout);
}

int soak(const SoakOptions& options) {
  std::vector<std::string> overrides = options.overrides;
  // Long enough for the requested steps, whatever the world's own duration (added last, so
  // it wins over a --set of run.duration).
  WorldSpec probe = load_world(options.world, overrides);
  overrides.push_back("run.duration=" +
                      format_number(static_cast<double>(options.steps) * probe.engine.dt));
  const WorldSpec spec = load_world(options.world, overrides);
  std::printf("soak: %s, %d agents, %s engine, %lld steps, invariants checked every step\n",
              spec.name.c_str(), spec.robots.count,
              spec.engine.type == EngineType::Box2D ? "box2d" : "kinematic",
              static_cast<long long>(options.steps));
  Replicate replicate(spec, 0);
  InvariantChecker checker;
  const auto start = Clock::now();
  try {
    for (std::int64_t k = 1; k <= options.steps; ++k) {
      replicate.step();
      checker.check(checked_state(replicate));
      if (k % 1'000'000 == 0) report(replicate, start);
    }
  } catch (const InvariantViolation& e) {
    report(replicate, start);
    std::printf("VIOLATION: %s\n", e.what());
    return 1;
  }
  const double elapsed = seconds_since(start);
  std::printf("done: %lld steps in %.1f s (%.0f steps/s, %.2f M agent-steps/s), no violation\n",
              static_cast<long long>(options.steps), elapsed,
              static_cast<double>(options.steps) / elapsed,
              static_cast<double>(options.steps) * spec.robots.count / elapsed / 1e6);
  return 0;
}

}  // namespace
}  // namespace swarmagg

int main(int argc, char** argv) {
  try {
    return swarmagg::soak(swarmagg::parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_soak: %s\n", e.what());
    return 2;
  }
}
