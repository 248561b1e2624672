#include "run/placement_sample.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "models/predictions.hpp"
#include "run/interrupt.hpp"
#include "run/parallel_for.hpp"
#include "run/replicate.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {
namespace {

constexpr int kSampledAgents = 1 << 18;
constexpr int kFewestPlacements = 8;
constexpr int kMostPlacements = 4096;
// Keeps the placements apart from every run's replicates (CounterRng::for_replicate of the
// world's seed).
constexpr std::uint64_t kPlacementStream = 0x9A7C3E1D5B2F4861ull;
// From this many agents placements are taken one at a time, each step on every thread: a
// replicate of 10^6 agents holds about 0.9 GB, and one per thread would multiply that.
constexpr int kOneAtATimeFrom = 1 << 16;

// The sizes of the aggregates after the first decision of placement `index`.
std::vector<std::int32_t> first_decision(const WorldSpec& world, int index, int step_threads) {
  throw_if_interrupted();  // thousands of placements, or a few large ones, take a while
  Replicate replicate(world, index);
  replicate.set_threads(step_threads);
  replicate.step();
  const std::span<const std::int32_t> sizes = replicate.aggregates().sizes();
  return {sizes.begin(), sizes.end()};
}

// The partition of `agents` that aggregates of these sizes leave: their sizes, decreasing, and
// a part of 1 for every agent in none.
Partition partition_of(std::vector<std::int32_t> sizes, int agents) {
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  Partition partition(sizes.begin(), sizes.end());
  int placed = 0;
  for (const int size : sizes) placed += size;
  partition.insert(partition.end(), static_cast<std::size_t>(agents - placed), 1);
  return partition;
}

}  // namespace

int placements_to_sample(int agents) {
  return std::clamp(kSampledAgents / std::max(agents, 1), kFewestPlacements, kMostPlacements);
}

PlacementSample sample_placements(const WorldSpec& world, int threads) {
  WorldSpec placing = world;
  placing.run.seed = mix64(world.run.seed ^ kPlacementStream);
  const int count = world.robots.random_placement() ? placements_to_sample(world.robots.count) : 1;
  std::vector<std::vector<std::int32_t>> sizes(static_cast<std::size_t>(count));
  const bool one_at_a_time = world.robots.count >= kOneAtATimeFrom;
  parallel_for(sizes.size(), one_at_a_time ? 1 : threads, [&](std::size_t i) {
    sizes[i] = first_decision(placing, static_cast<int>(i), one_at_a_time ? threads : 1);
  });
  // Sums of whole counts, taken in placement order: the same for any thread count.
  std::vector<std::uint64_t> totals(static_cast<std::size_t>(world.robots.count) + 1, 0);
  std::map<Partition, int> partitions;
  const bool small = world.robots.count <= kSampledPartitionsUpTo;
  double noa_sum = 0.0, noa_square_sum = 0.0;
  for (const std::vector<std::int32_t>& placement : sizes) {
    for (const std::int32_t size : placement) ++totals[static_cast<std::size_t>(size)];
    const auto noa = static_cast<double>(placement.size());
    noa_sum += noa;
    noa_square_sum += noa * noa;
    if (small) ++partitions[partition_of(placement, world.robots.count)];
  }
  PlacementSample sample;
  sample.placements = count;
  for (const auto& [partition, times] : partitions)
    sample.partitions[partition] = static_cast<double>(times) / count;
  sample.aggregates.resize(totals.size(), 0.0);
  for (std::size_t m = 2; m < totals.size(); ++m)
    sample.aggregates[m] = static_cast<double>(totals[m]) / count;
  if (count > 1) {
    const double mean = noa_sum / count;
    const double variance = std::max(0.0, (noa_square_sum - count * mean * mean) / (count - 1));
    sample.noa_standard_error = std::sqrt(variance / count);
  }
  return sample;
}

std::optional<PlacementSample> placement_start(const WorldSpec& world, int threads) {
  if (!starts_from_placement_sample(world)) return std::nullopt;
  try {
    return sample_placements(world, resolve_threads(world, threads));
  } catch (const InputError& e) {
    // A nearly full arena jams now and then: among the sample's hundreds or thousands of
    // placements one may, though every replicate of a run placed its agents.
    const int count =
        world.robots.random_placement() ? placements_to_sample(world.robots.count) : 1;
    throw InputError("the models' start (model.initial_state: placement) draws " +
                     std::to_string(count) + " placements, and one failed: " + e.what() +
                     "; set model.initial_state: placement_second_order or all_searching");
  }
}

std::optional<PlacementSample> placement_start_or_reason(const WorldSpec& world, int threads,
                                                         std::string& why) {
  try {
    return placement_start(world, threads);
  } catch (const InputError& e) {
    why = e.what();
    return std::nullopt;
  }
}

std::string second_order_initial_note(const std::string& why) {
  return "the rates' `initial` rows take their model values from the second-order formula: " + why;
}

std::string placement_start_note(const PlacementSample& sample) {
  double noa = 0.0;
  for (const double aggregates : sample.aggregates) noa += aggregates;
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "%.4g +- %.2g", noa, sample.noa_standard_error);
  const std::string placements = sample.placements == 1
                                     ? "the given positions"
                                     : "the mean of " + std::to_string(sample.placements) +
                                           " random placements drawn as the runs draw theirs";
  return "from step 1 the models start where the first decision leaves the swarm, " +
         std::string(numbers) + " aggregates: " + placements +
         " (model.initial_state: placement); at step 0, as in the runs, no agent waits";
}

std::vector<PendingVariant> pending_world_predictions(const WorldSpec& world,
                                                      const MeasuredTerms* measured, int threads) {
  const std::optional<PlacementSample> sample = placement_start(world, threads);
  return pending_predictions(world, measured, sample ? &*sample : nullptr);
}

std::vector<VariantPrediction> predict_world(const WorldSpec& world, const MeasuredTerms* measured,
                                             int threads) {
  std::vector<VariantPrediction> predictions;
  for (const PendingVariant& pending : pending_world_predictions(world, measured, threads))
    predictions.push_back(collect(pending));
  return predictions;
}

}  // namespace swarmagg
