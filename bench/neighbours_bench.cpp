// The neighbour structures, per step: the arena's pair finder (geometry/pair_finder.hpp,
// rebuilt and scanned; the engine's fallback for small worlds), the sorted strips (re-sorted
// from the previous order, then scanned) and the whole search the engine runs (strips,
// candidates within v-dependent reach and perceived pairs within s). Positions
// alternate between two states one step apart, so each update sees one step's movement.
//
//   build/bench/bench_neighbours [--benchmark_filter=Strips]
#include <benchmark/benchmark.h>

#include "bench_inputs.hpp"
#include "engine/kinematic/neighbour_search.hpp"
#include "engine/kinematic/sorted_strips.hpp"
#include "geometry/pair_finder.hpp"

namespace swarmagg::bench {
namespace {

// The engine's radii at v = 1: perception within s, candidates within s + 2 v dt.
constexpr double kSensing = 4.0;
constexpr double kPairReach = 4.0 + 2.0 * 1.0 * 0.1;

struct GhostPositions {
  SteppedWorld world;
  ArenaGeometry arena;
  std::vector<Vec2> now, next;

  explicit GhostPositions(int n) : world(n, "collision", 0), arena(world.spec.arena.geometry()) {
    const auto p = world.replicate->engine().positions();
    now.assign(p.begin(), p.end());
    next = moved_one_step(world);
  }
  const std::vector<Vec2>& at(std::int64_t iteration) const {
    return iteration % 2 == 0 ? now : next;
  }
};

void BM_PairFinderRebuild(benchmark::State& state) {
  const GhostPositions input(static_cast<int>(state.range(0)));
  PairFinder finder;
  std::int64_t k = 0;
  for (auto _ : state) {
    finder.reset(input.arena, kPairReach, input.now.size());
    for (const Vec2& p : input.at(k++)) finder.add(p);
  }
  count_items(state, input.now.size());
}
BENCHMARK(BM_PairFinderRebuild)->Apply(agent_counts);

void BM_PairFinderPairs(benchmark::State& state) {
  const GhostPositions input(static_cast<int>(state.range(0)));
  PairFinder finder;
  finder.reset(input.arena, kPairReach, input.now.size());
  for (const Vec2& p : input.now) finder.add(p);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = 0;
    finder.for_each_pair([&](std::uint32_t, std::uint32_t, Vec2) { ++pairs; });
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = static_cast<double>(pairs);
  count_items(state, input.now.size());
}
BENCHMARK(BM_PairFinderPairs)->Apply(agent_counts);

void BM_SortedStripsUpdate(benchmark::State& state) {
  const GhostPositions input(static_cast<int>(state.range(0)));
  SortedStrips strips;
  StepThreads threads;
  strips.update(input.arena, kPairReach, input.next, threads);  // sorted from scratch once
  std::int64_t k = 0;
  for (auto _ : state) strips.update(input.arena, kPairReach, input.at(k++), threads);
  count_items(state, input.now.size());
}
BENCHMARK(BM_SortedStripsUpdate)->Apply(agent_counts);

void BM_SortedStripsCandidates(benchmark::State& state) {
  const GhostPositions input(static_cast<int>(state.range(0)));
  SortedStrips strips;
  StepThreads threads;
  strips.update(input.arena, kPairReach, input.now, threads);
  std::size_t candidates = 0;
  for (auto _ : state) {
    candidates = 0;
    strips.for_each_candidate(0, strips.strips(),
                              [&](std::uint32_t, std::uint32_t) { ++candidates; });
    benchmark::DoNotOptimize(candidates);
  }
  state.counters["candidates"] = static_cast<double>(candidates);
  count_items(state, input.now.size());
}
BENCHMARK(BM_SortedStripsCandidates)->Apply(agent_counts);

// What the engine pays per step for its neighbourhood (one thread).
void BM_NeighbourSearchFind(benchmark::State& state) {
  const GhostPositions input(static_cast<int>(state.range(0)));
  NeighbourSearch search;
  StepThreads threads;
  const SearchRadii radii{kSensing, kPairReach, true};
  std::int64_t k = 0;
  for (auto _ : state) {
    search.find(input.arena, input.at(k++), radii, threads);
    benchmark::DoNotOptimize(search.candidates().data());
  }
  state.counters["candidates"] = static_cast<double>(search.candidates().size());
  state.counters["perceived"] = static_cast<double>(search.close_pairs().size());
  count_items(state, input.now.size());
}
BENCHMARK(BM_NeighbourSearchFind)->Apply(agent_counts);

}  // namespace
}  // namespace swarmagg::bench
