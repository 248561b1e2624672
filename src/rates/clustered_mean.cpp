#include "rates/clustered_mean.hpp"

#include <algorithm>
#include <cmath>

#include "models/sample_statistics.hpp"

namespace swarmagg {

void ClusteredMean::add_cluster(std::uint64_t count, double sum) {
  if (count == 0) return;
  const auto n = static_cast<double>(count);
  observations_ += count;
  ++clusters_;
  sum_ += sum;
  sum_squares_ += sum * sum;
  sum_cross_ += sum * n;
  count_squares_ += n * n;
}

void ClusteredMean::merge(const ClusteredMean& other) {
  observations_ += other.observations_;
  clusters_ += other.clusters_;
  sum_ += other.sum_;
  sum_squares_ += other.sum_squares_;
  sum_cross_ += other.sum_cross_;
  count_squares_ += other.count_squares_;
}

RateEstimate ClusteredMean::estimate() const {
  const auto n = static_cast<double>(observations_);
  RateEstimate estimate{.events = observations_, .exposure = n};
  if (observations_ < kMinimumEvents || clusters_ < 2) return estimate;
  const double mean = sum_ / n;
  const auto k = static_cast<double>(clusters_);
  // sum_j (S_j - mean n_j)^2, expanded; rounding may leave it a hair below 0.
  const double scatter =
      std::max(0.0, sum_squares_ - 2.0 * mean * sum_cross_ + mean * mean * count_squares_);
  const double standard_error = std::sqrt(k / (k - 1.0) * scatter) / n;
  const double half_width = student_t_quantile(k - 1.0, 0.95) * standard_error;
  estimate.rate = mean;
  estimate.low = std::max(0.0, mean - half_width);
  estimate.high = mean + half_width;
  return estimate;
}

}  // namespace swarmagg
