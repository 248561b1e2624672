// The controller step, decide(): Bayindir's full model (leaving, joining, pairing searchers
// greedily by distance, steering) on its state after pairs and aggregates have formed, and
// the ghost controller (tumble and copy) for comparison. decide() changes the swarm state,
// so every iteration starts from a copy made outside the clock.
//
//   build/bench/bench_controller
#include <benchmark/benchmark.h>

#include "bench_inputs.hpp"
#include "controllers/controller.hpp"

namespace swarmagg::bench {
namespace {

void decide_repeatedly(benchmark::State& state, const std::string& type, int warm_up) {
  const SteppedWorld world(static_cast<int>(state.range(0)), type, warm_up);
  const Replicate& r = *world.replicate;
  const auto controller = make_controller(world.spec);
  const ControllerInput input{r.steps_done(), r.engine().neighbours(), r.engine().reflections(),
                              r.aggregates().facts()};
  const CounterRng rng(r.seed());
  std::vector<MotionCommand> commands(r.swarm().size());
  SwarmState swarm;
  EventCounts events;
  for (auto _ : state) {
    state.PauseTiming();
    swarm = r.swarm();
    state.ResumeTiming();
    controller->decide(input, swarm, rng, commands, events);
    benchmark::DoNotOptimize(commands.data());
  }
  count_items(state, r.swarm().size());
}

void BM_BayindirDecide(benchmark::State& state) {
  decide_repeatedly(state, "bayindir", kWarmUpSteps);
}
BENCHMARK(BM_BayindirDecide)->Apply(agent_counts);

void BM_GhostDecide(benchmark::State& state) {
  decide_repeatedly(state, "collision", 0);
}
BENCHMARK(BM_GhostDecide)->Apply(agent_counts);

}  // namespace
}  // namespace swarmagg::bench
