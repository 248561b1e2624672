// Aggregate detection: the union-find over waiting agents linked within s (torus-aware
// through the neighbour lists), recomputed from scratch every step, on the state of
// Bayindir's full model after pairs and aggregates have formed.
//
//   build/bench/bench_aggregates
#include <benchmark/benchmark.h>

#include "bench_inputs.hpp"
#include "observers/aggregate_tracker.hpp"

namespace swarmagg::bench {
namespace {

void BM_AggregateTrackerUpdate(benchmark::State& state) {
  const SteppedWorld world(static_cast<int>(state.range(0)), "bayindir", kWarmUpSteps);
  const Replicate& r = *world.replicate;
  AggregateTracker tracker;
  for (auto _ : state) {
    tracker.update(r.engine().neighbours(), r.swarm(), world.spec.robots.detection_radius,
                   AggregateLinks::Proximity);
    benchmark::DoNotOptimize(tracker.count());
  }
  std::size_t waiting = 0;
  for (const AgentState s : r.swarm().state) waiting += s == AgentState::Wait;
  state.counters["waiting"] = static_cast<double>(waiting);
  state.counters["aggregates"] = tracker.count();
  count_items(state, r.swarm().size());
}
BENCHMARK(BM_AggregateTrackerUpdate)->Apply(agent_counts);

}  // namespace
}  // namespace swarmagg::bench
