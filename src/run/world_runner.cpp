#include "run/world_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "observers/partition_tracker.hpp"
#include "run/interrupt.hpp"
#include "run/parallel_for.hpp"
#include "run/partition_recording.hpp"
#include "run/progress_line.hpp"
#include "run/recorded_steps.hpp"
#include "run/replicate.hpp"
#include "run/state_hash.hpp"
#include "run/timeseries_spool.hpp"

namespace swarmagg {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void record(const Replicate& replicate, ReplicateOutcome& outcome, TimeseriesSpool* timeseries,
            bool keep_rows) {
  outcome.final_row = observe_row(replicate.index(), replicate.snapshot(), replicate.aggregates(),
                                  replicate.events());
  if (timeseries) {
    timeseries->append(replicate.index(), outcome.final_row);
  } else if (keep_rows) {
    outcome.rows.push_back(outcome.final_row);
  }
}

std::vector<AggregateShape> final_shapes(const Replicate& replicate) {
  AggregateMembers members;
  members.build(replicate.aggregates());
  return measure_aggregates(members, replicate.engine().positions(),
                            ShapeRules::for_world(replicate.spec()));
}

}  // namespace

int resolve_threads(const WorldSpec& spec, int requested) {
  const int threads = requested > 0 ? requested : spec.run.threads;
  if (threads > 0) return threads;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

ThreadPlan plan_threads(const WorldSpec& spec, int requested) {
  const int threads = resolve_threads(spec, requested);
  const int at_once = std::clamp(threads, 1, spec.run.replicates);
  // Box2D steps a world on one thread (Engine::set_threads does nothing there).
  const bool splits_steps = spec.engine.type == EngineType::Kinematic;
  return {at_once, splits_steps ? std::max(1, threads / at_once) : 1};
}

ReplicateOutcome run_replicate(const WorldSpec& spec, int index, ReplicateObserver* observer,
                               const ReplicateRunOptions& how) {
  const auto start = Clock::now();
  Replicate replicate(spec, index);
  if (how.check) replicate.set_checking(true);
  replicate.set_threads(how.step_threads);
  ReplicateOutcome outcome;
  outcome.index = index;
  outcome.seed = replicate.seed();
  const std::int64_t steps = spec.steps();
  const bool partitions = records_partitions(spec);
  PartitionTracker partition_tracker;
  const int n = spec.robots.count;
  if (!how.timeseries && how.keep_rows)
    outcome.rows.reserve(static_cast<std::size_t>(steps / spec.run.record_every + 2));
  record(replicate, outcome, how.timeseries, how.keep_rows);
  if (observer) observer->observe(replicate);
  for (std::int64_t k = 1; k <= steps; ++k) {
    replicate.step();
    if (partitions) partition_tracker.observe(replicate.aggregates(), n);
    if (is_recorded_step(spec, k)) record(replicate, outcome, how.timeseries, how.keep_rows);
    if (observer) observer->observe(replicate);
    throw_if_interrupted();
  }
  if (observer) observer->finish();
  if (how.timeseries) how.timeseries->close(index);
  const auto sizes = replicate.aggregates().sizes();
  outcome.final_aggregate_sizes.assign(sizes.begin(), sizes.end());
  outcome.final_aggregates = final_shapes(replicate);
  outcome.leave = replicate.leave_episodes().tally();
  outcome.partition_steps = partition_tracker.steps_by_partition();
  outcome.final_state_hash = state_hash(replicate);
  outcome.wall_seconds = seconds_since(start);
  return outcome;
}

RunResult run_world(const WorldSpec& spec, const RunOptions& options) {
  const auto start = Clock::now();
  RunResult result;
  const ThreadPlan plan = plan_threads(spec, options.threads);
  result.threads = plan.replicates_at_once;
  result.step_threads = plan.step_threads;
  result.replicates.resize(static_cast<std::size_t>(spec.run.replicates));
  const int agents = spec.robots.count;
  const std::int64_t steps = spec.steps();
  ProgressLine progress(
      spec.name, "replicates", spec.run.replicates,
      static_cast<double>(agents) * static_cast<double>(steps) * spec.run.replicates);
  auto run_one = [&](std::size_t index) {
    const int i = static_cast<int>(index);
    ObserverGroup observers;
    observers.add(std::make_unique<ProgressObserver>(progress, agents, steps));
    if (options.observers) observers.add(options.observers(i));
    result.replicates[index] = run_replicate(spec, i, &observers,
                                             {.check = options.check,
                                              .step_threads = plan.step_threads,
                                              .timeseries = options.timeseries,
                                              .keep_rows = options.keep_rows});
    progress.finished_unit();
  };
  parallel_for(result.replicates.size(), result.threads, run_one,
               options.progress ? std::function<void()>([&] { progress.report(); }) : nullptr);
  if (options.progress) progress.finish();
  result.wall_seconds = seconds_since(start);
  return result;
}

}  // namespace swarmagg
