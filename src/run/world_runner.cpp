#include "run/world_runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "observers/partition_tracker.hpp"
#include "run/interrupt.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Steps done by every replicate of the current run, for the progress line.
std::atomic<std::int64_t> steps_done_total{0};

void record(const Replicate& replicate, ReplicateOutcome& outcome) {
  outcome.rows.push_back(observe_row(replicate.index(), replicate.snapshot(),
                                     replicate.aggregates(), replicate.events()));
}

std::vector<AggregateShape> final_shapes(const Replicate& replicate) {
  AggregateMembers members;
  members.build(replicate.aggregates());
  return measure_aggregates(members, replicate.engine().positions(),
                            ShapeRules::for_world(replicate.spec()));
}

void report_progress(const WorldSpec& spec, std::int64_t total, Clock::time_point start) {
  const double fraction = static_cast<double>(steps_done_total.load()) / static_cast<double>(total);
  const double elapsed = seconds_since(start);
  const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r%s: %5.1f%%  elapsed %.0fs  eta %.0fs   ", spec.name.c_str(),
               100.0 * fraction, elapsed, eta);
  std::fflush(stderr);
}

}  // namespace

ThreadPlan plan_threads(const WorldSpec& spec, int requested) {
  int threads = requested > 0 ? requested : spec.run.threads;
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(threads, 1);
  const int at_once = std::clamp(threads, 1, spec.run.replicates);
  return {at_once, std::max(1, threads / at_once)};
}

ReplicateOutcome run_replicate(const WorldSpec& spec, int index, ReplicateObserver* observer,
                               bool check, int step_threads) {
  const auto start = Clock::now();
  Replicate replicate(spec, index);
  if (check) replicate.set_checking(true);
  replicate.set_threads(step_threads);
  ReplicateOutcome outcome;
  outcome.index = index;
  outcome.seed = replicate.seed();
  const std::int64_t steps = spec.steps();
  const bool partitions = spec.controller.type == ControllerType::Soysal;
  PartitionTracker partition_tracker;
  const int n = spec.robots.count;
  outcome.rows.reserve(static_cast<std::size_t>(steps / spec.run.record_every + 2));
  record(replicate, outcome);
  if (observer) observer->observe(replicate);
  for (std::int64_t k = 1; k <= steps; ++k) {
    replicate.step();
    if (partitions) partition_tracker.observe(replicate.aggregates(), n);
    if (k % spec.run.record_every == 0 || k == steps) record(replicate, outcome);
    if (observer) observer->observe(replicate);
    if ((k & 1023) == 0) {
      steps_done_total.fetch_add(1024, std::memory_order_relaxed);
      throw_if_interrupted();
    }
  }
  steps_done_total.fetch_add(steps & 1023, std::memory_order_relaxed);
  if (observer) observer->finish();
  const auto sizes = replicate.aggregates().sizes();
  outcome.final_aggregate_sizes.assign(sizes.begin(), sizes.end());
  outcome.final_aggregates = final_shapes(replicate);
  outcome.leave = replicate.leave_episodes().tally();
  outcome.partition_steps = partition_tracker.steps_by_partition();
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
  steps_done_total.store(0);
  std::atomic<int> next{0};
  std::atomic<int> finished{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (int index = next++; index < spec.run.replicates; index = next++) {
      try {
        auto observer = options.observers ? options.observers(index) : nullptr;
        result.replicates[static_cast<std::size_t>(index)] =
            run_replicate(spec, index, observer.get(), options.check, plan.step_threads);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = spec.run.replicates;  // stop handing out work
      }
      ++finished;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < result.threads; ++t) pool.emplace_back(worker);
  const bool show = options.progress && ::isatty(::fileno(stderr));
  const std::int64_t total = spec.steps() * spec.run.replicates;
  while (show && finished.load() < spec.run.replicates) {
    report_progress(spec, total, start);
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  for (std::thread& t : pool) t.join();
  if (show) std::fprintf(stderr, "\r%*s\r", 60, "");
  if (failure) std::rethrow_exception(failure);
  result.wall_seconds = seconds_since(start);
  return result;
}

}  // namespace swarmagg
