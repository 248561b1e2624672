// The encounter (swept contact) solver of the kinematic engine: the exact first-contact time
// of one pair (a quadratic's smaller root), every pair of a ghost step counted without
// guards (the worst case: all agents move, nobody halts), and a guarded step of Bayindir's
// full model, where searchers halt at the instant they perceive one another or a waiting
// agent, events are processed in time order and halted agents' pairs are rescheduled.
//
//   build/bench/bench_encounters
#include <benchmark/benchmark.h>

#include "bench_inputs.hpp"
#include "controllers/controller.hpp"
#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/neighbour_search.hpp"
#include "geometry/swept_contact.hpp"

namespace swarmagg::bench {
namespace {

// What one engine step of `world` resolves: its candidate pairs, the controller's commands
// and the signals (states) the agents display.
struct StepInput {
  SteppedWorld world;
  NeighbourSearch search;
  std::vector<MotionCommand> commands;
  std::vector<Signal> signals;
  MotionLimits limits;

  StepInput(int n, const std::string& type, int steps) : world(n, type, steps) {
    const WorldSpec& spec = world.spec;
    const Replicate& r = *world.replicate;
    StepThreads threads;
    const double v = spec.robots.speed;
    search.find(
        spec.arena.geometry(), r.engine().positions(),
        {spec.sensing_radius(), spec.robots.detection_radius + 2.0 * v * spec.engine.dt, false},
        threads);
    SwarmState swarm = r.swarm();
    commands.resize(swarm.size());
    EventCounts events;
    const ControllerInput input{r.steps_done(), r.engine().neighbours(), r.engine().reflections(),
                                r.aggregates().facts()};
    make_controller(spec)->decide(input, swarm, CounterRng(r.seed()), commands, events);
    signals.resize(swarm.size());
    write_signals(swarm.state, signals);
    limits = {spec.robots.detection_radius * (1.0 - 1e-9),
              2.0 * spec.robots.radius,
              spec.engine.dt,
              spec.engine.contact,
              false,
              {}};
  }
};

void BM_FirstContactTime(benchmark::State& state) {
  const StepInput input(10000, "collision", 0);
  const auto pairs = input.search.candidates();
  std::size_t met = 0;
  for (auto _ : state) {
    met = 0;
    for (const CandidatePair& p : pairs) {
      const Vec2 w = input.commands[p.j].velocity - input.commands[p.i].velocity;
      met += first_contact_time(p.offset, w, input.limits.detection_radius, 0.0, input.limits.dt)
                 .has_value();
    }
    benchmark::DoNotOptimize(met);
  }
  state.counters["meeting"] = static_cast<double>(met);
  count_items(state, pairs.size());  // pairs per second
}
BENCHMARK(BM_FirstContactTime)->Unit(benchmark::kMicrosecond);

void BM_GhostEncounters(benchmark::State& state) {
  const StepInput input(static_cast<int>(state.range(0)), "collision", 0);
  std::uint64_t encounters = 0;
  for (auto _ : state) {
    encounters =
        GuardedMotion::count_encounters(input.search.candidates(), input.commands, input.limits);
    benchmark::DoNotOptimize(encounters);
  }
  state.counters["candidates"] = static_cast<double>(input.search.candidates().size());
  state.counters["encounters"] = static_cast<double>(encounters);
  count_items(state, input.commands.size());
}
BENCHMARK(BM_GhostEncounters)->Apply(agent_counts);

void BM_BayindirGuardedStep(benchmark::State& state) {
  const StepInput input(static_cast<int>(state.range(0)), "bayindir", kWarmUpSteps);
  GuardedMotion motion;
  std::uint64_t encounters = 0;
  for (auto _ : state) {
    encounters =
        motion.resolve(input.search.candidates(), input.commands, input.signals, input.limits);
    benchmark::DoNotOptimize(encounters);
  }
  std::size_t halted = 0;  // halted or slid: moved other than commanded
  for (std::uint32_t a = 0; a < input.commands.size(); ++a) {
    halted += motion.displacement(a) != input.commands[a].velocity * input.limits.dt;
  }
  state.counters["candidates"] = static_cast<double>(input.search.candidates().size());
  state.counters["halted"] = static_cast<double>(halted);
  count_items(state, input.commands.size());
}
BENCHMARK(BM_BayindirGuardedStep)->Apply(agent_counts);

}  // namespace
}  // namespace swarmagg::bench
