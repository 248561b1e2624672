#pragma once
// Fills a RateTally from one replicate, observed after setup (step 0) and after every step.
// The events a step counts were decided from the state observed after the step before
// (decisions read the previous step's states and neighbours), so the exposure of the state
// observed at step k is paired with the events counted during step k + 1. Step 1 is the
// first decision: it pairs agents that random placement put within s of each other, which
// no encounter rate describes, so its events and the exposure of step 0 are left out, and
// its outcome is recorded as the initial state instead (docs/models.md). The state observed at
// the last step has no decision after it and adds no exposure.
//
// The aggregates' geometry is observed separately (observe_shape, at the recorded steps
// after the first decision: measuring shapes costs O(m^2) per aggregate) and summed per size;
// finish() turns the replicate's sums into one cluster of each size's ClusteredMean.
#include <cstdint>
#include <span>

#include "rates/rate_tally.hpp"

namespace swarmagg {

class RateRecorder {
 public:
  RateRecorder(int agents, std::int64_t last_step);

  // `free_agents`: the searchers y; `aggregate_sizes`: every aggregate's size; `creations`
  // and `growths_by_size` ([m], cumulative) the replicate's counts so far.
  void observe(std::int64_t step, int free_agents, std::span<const std::int32_t> aggregate_sizes,
               std::uint64_t creations, std::span<const std::uint64_t> growths_by_size);
  // One aggregate of `size` members observed with outer radius R1 and `rim` rim members.
  void observe_shape(int size, double outer_radius, int rim);
  // The replicate's tally (events after the first decision), once the last step is observed.
  RateTally finish() const;

 private:
  RateTally tally_;
  std::int64_t last_step_;
  std::uint64_t creations_at_first_ = 0, creations_now_ = 0;
  std::vector<std::uint64_t> growths_at_first_, growths_now_;
  std::vector<std::uint64_t> shapes_by_size_;   // [m] observations of this replicate
  std::vector<double> radius_sums_, rim_sums_;  // [m]
};

}  // namespace swarmagg
