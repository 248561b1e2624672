#include "rates/rate_recorder.hpp"

#include <algorithm>

namespace swarmagg {

RateRecorder::RateRecorder(int agents, std::int64_t last_step)
    : tally_(agents),
      last_step_(last_step),
      growths_at_first_(static_cast<std::size_t>(agents) + 1, 0),
      growths_now_(static_cast<std::size_t>(agents) + 1, 0),
      shapes_by_size_(static_cast<std::size_t>(agents) + 1, 0),
      radius_sums_(static_cast<std::size_t>(agents) + 1, 0.0),
      rim_sums_(static_cast<std::size_t>(agents) + 1, 0.0) {
  tally_.replicates = 1;
}

void RateRecorder::observe(std::int64_t step, int free_agents,
                           std::span<const std::int32_t> aggregate_sizes, std::uint64_t creations,
                           std::span<const std::uint64_t> growths_by_size) {
  if (step == 0) return;
  const std::size_t sizes = std::min(growths_now_.size(), growths_by_size.size());
  // Only the counts after the first decision and at the end matter: copying the per-size
  // counters every step would cost O(N) per step.
  creations_now_ = creations;
  if (step >= last_step_) std::copy_n(growths_by_size.begin(), sizes, growths_now_.begin());
  if (step == 1) {
    creations_at_first_ = creations;
    std::copy_n(growths_by_size.begin(), sizes, growths_at_first_.begin());
    for (const std::int32_t size : aggregate_sizes) ++tally_.initial_aggregates[size];
  }
  if (step >= last_step_) return;
  const auto y = static_cast<std::uint64_t>(free_agents);
  ++tally_.steps;
  tally_.pair_steps += y * (y - (y > 0 ? 1 : 0)) / 2;
  for (const std::int32_t size : aggregate_sizes) {
    tally_.searcher_aggregate_steps[size] += y;
    ++tally_.aggregate_steps[size];
  }
}

void RateRecorder::observe_shape(int size, double outer_radius, int rim) {
  const auto m = static_cast<std::size_t>(size);
  ++shapes_by_size_.at(m);
  radius_sums_[m] += outer_radius;
  rim_sums_[m] += rim;
}

RateTally RateRecorder::finish() const {
  RateTally tally = tally_;
  tally.creations = creations_now_ - creations_at_first_;
  for (std::size_t m = 0; m < tally.growths.size(); ++m) {
    tally.growths[m] = growths_now_[m] - growths_at_first_[m];
    tally.outer_radius[m].add_cluster(shapes_by_size_[m], radius_sums_[m]);
    tally.rim[m].add_cluster(shapes_by_size_[m], rim_sums_[m]);
  }
  return tally;
}

}  // namespace swarmagg
