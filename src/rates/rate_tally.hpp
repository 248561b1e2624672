#pragma once
// The events and exposures of docs/models.md, summed over the steps of one or more replicates.
// Exposures are kept in steps (whole numbers, so sums are exact and independent of the
// order replicates are merged in); multiply by dt for tu. "Searchers" are the model's y:
// every agent in no aggregate (a LEAVE agent too: the models have no leave timeout), or
// all N agents in a collision world (every agent keeps moving there).
#include <cstdint>
#include <vector>

#include "rates/clustered_mean.hpp"

namespace swarmagg {

struct RateTally {
  int agents = 0;
  int replicates = 0;
  std::uint64_t steps = 0;             // steps of exposure, over all replicates
  std::uint64_t creations = 0;         // creations (collision worlds: encounters) after step 1
  std::vector<std::uint64_t> growths;  // [m] growths into an aggregate of size m after step 1
  std::uint64_t pair_steps = 0;        // sum of y (y - 1) / 2
  std::vector<std::uint64_t> searcher_aggregate_steps;  // [m] sum of y n_m
  std::vector<std::uint64_t> aggregate_steps;           // [m] sum of n_m
  // [m] aggregates of size m right after the first decision, summed over replicates.
  std::vector<std::uint64_t> initial_aggregates;
  // LEAVE episodes by the size m of the aggregate left (observers/leave_episodes.hpp): the
  // attempts, the escapes and their exposure (aggregates of size m at each decision).
  std::vector<std::uint64_t> attempts, escapes, leave_aggregate_steps;
  // Returns (a leaver back in an aggregate holding a member of the one it left who kept
  // waiting, within rates.return_window; observers/leave_episodes.hpp): [m] by the size m left, the
  // attempts whose window closed within the run, the returns among them and their summed steps away
  // (and squares); [j] by the size j of the aggregate joined on return (0: a lone member that kept
  // waiting); [k] the searcher-aggregate steps (y n_k) of returning agents while away, which new
  // joins leave out of their exposure (these two over every return).
  std::vector<std::uint64_t> return_attempts, returns, return_steps, return_square_steps,
      returns_into, returning_searcher_steps;
  // [m] the geometry of size-m aggregates (docs/models.md) observed at the recorded steps after the
  // first decision, one cluster per replicate: outer radius R1 and rim count.
  std::vector<ClusteredMean> outer_radius, rim;

  explicit RateTally(int agent_count = 0);
  void merge(const RateTally& other);
};

}  // namespace swarmagg
