#include "rates/binomial_interval.hpp"

#include <boost/math/special_functions/beta.hpp>

namespace swarmagg {

RateEstimate estimate_fraction(std::uint64_t successes, std::uint64_t trials) {
  const auto n = static_cast<double>(trials);
  const auto k = static_cast<double>(successes);
  RateEstimate estimate{.events = successes, .exposure = n};
  if (trials < kMinimumEvents || successes > trials) return estimate;
  constexpr double kTail = 0.025;
  estimate.rate = k / n;
  estimate.low = successes == 0 ? 0.0 : boost::math::ibeta_inv(k, n - k + 1.0, kTail);
  estimate.high = successes == trials ? 1.0 : boost::math::ibeta_inv(k + 1.0, n - k, 1.0 - kTail);
  return estimate;
}

}  // namespace swarmagg
