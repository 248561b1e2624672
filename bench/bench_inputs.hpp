#pragma once
// Realistic inputs for the hot-path micro-benchmarks (issue 8): N agents at the paper's
// density (150 per 180 x 180, the square arena scaled with N) with the default robots of
// WorldSpec (r = 1, s = 4, v = 1, dt = 0.1), either freshly placed (ghosts: uniform, the
// stationary state of an ideal gas) or a replicate of Bayindir's full model (p = 0.001)
// stepped until pairs and aggregates have formed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "bench/lib/paper_density_world.hpp"
#include "config/world_loader.hpp"
#include "config/world_spec.hpp"
#include "run/replicate.hpp"

namespace swarmagg::bench {

// Steps a Bayindir replicate runs before its state is measured.
constexpr int kWarmUpSteps = 150;

// A replicate of `spec` (kept alive beside it) after `steps` steps.
struct SteppedWorld {
  WorldSpec spec;
  std::unique_ptr<Replicate> replicate;

  SteppedWorld(int n, const std::string& type, int steps)
      : spec(paper_density_world(n, type)), replicate(std::make_unique<Replicate>(spec, 0)) {
    replicate->set_checking(false);
    for (int k = 0; k < steps; ++k) replicate->step();
  }
};

// The positions one step of dt later, every agent moving at speed v along its heading
// (wrapped on the torus): alternating between the two gives structures that are updated
// from the previous order a realistic step's worth of movement.
inline std::vector<Vec2> moved_one_step(const SteppedWorld& world) {
  const auto& positions = world.replicate->engine().positions();
  const auto& heading = world.replicate->swarm().heading;
  const double step = world.spec.robots.speed * world.spec.engine.dt;
  const double side = world.spec.arena.width;
  std::vector<Vec2> moved(positions.begin(), positions.end());
  for (std::size_t i = 0; i < moved.size(); ++i) {
    moved[i] += heading[i] * step;
    moved[i].x = std::fmod(moved[i].x + side, side);
    moved[i].y = std::fmod(moved[i].y + side, side);
  }
  return moved;
}

// Throughput in agents (or pairs) per second: Google Benchmark prints items_per_second.
inline void count_items(benchmark::State& state, std::size_t per_iteration) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(per_iteration));
}

// N = 10^3, 10^4, 10^5.
inline void agent_counts(benchmark::internal::Benchmark* b) {
  b->ArgName("agents")->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);
}

}  // namespace swarmagg::bench
