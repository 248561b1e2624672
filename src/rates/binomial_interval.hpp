#pragma once
// A fraction measured as successes out of trials (the returns among LEAVE attempts), with the
// exact (Clopper-Pearson) 95% interval from the beta quantiles
//   low = Q_beta(k, n - k + 1; 0.025) (0 for k = 0),  high = Q_beta(k + 1, n - k; 0.975)
// (1 for k = n). As for rates, fewer than kMinimumEvents trials give no fraction at all.
#include <cstdint>

#include "rates/poisson_interval.hpp"

namespace swarmagg {

// events: the successes; exposure: the trials; rate, low, high: the fraction and interval.
RateEstimate estimate_fraction(std::uint64_t successes, std::uint64_t trials);

}  // namespace swarmagg
