#pragma once
// A mean over observations that come in independent clusters: the aggregate geometry of
// docs/models.md (outer radius, rim count by size) observed at every recorded step of every
// replicate. Observations of one replicate are not independent (the same aggregate is seen
// at successive recorded steps), replicates are, so the interval treats each replicate as
// one cluster: the pooled mean sum x / N with the cluster-robust (ratio estimator) variance
//   Var = k / (k - 1) * sum_j (S_j - mean n_j)^2 / N^2
// over the k replicates with observations (n_j observations summing to S_j), and the
// Student t quantile at k - 1 degrees. The quantities averaged are never negative, so the
// interval's lower end is cut at 0 (with two replicates the t quantile is 12.7, and the
// symmetric interval of a rim count could reach below 0; the cut keeps its coverage).
// Everything is kept as sums, so tallies merge in any grouping. Fewer than kMinimumEvents
// observations, or observations from fewer than two replicates, give no mean (too few), as the
// rates do.
#include <cstdint>

#include "rates/poisson_interval.hpp"

namespace swarmagg {

class ClusteredMean {
 public:
  // One replicate's observations: `count` values summing to `sum`.
  void add_cluster(std::uint64_t count, double sum);
  void merge(const ClusteredMean& other);

  std::uint64_t observations() const { return observations_; }
  std::uint64_t clusters() const { return clusters_; }
  // The mean (as `rate`, events = exposure = observations) with its 95% interval.
  RateEstimate estimate() const;

 private:
  std::uint64_t observations_ = 0;  // N
  std::uint64_t clusters_ = 0;      // k
  double sum_ = 0.0;                // sum_j S_j
  double sum_squares_ = 0.0;        // sum_j S_j^2
  double sum_cross_ = 0.0;          // sum_j S_j n_j
  double count_squares_ = 0.0;      // sum_j n_j^2
};

}  // namespace swarmagg
