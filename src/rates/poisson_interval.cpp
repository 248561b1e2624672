#include "rates/poisson_interval.hpp"

#include <boost/math/special_functions/gamma.hpp>
#include <stdexcept>

namespace swarmagg {

PoissonInterval garwood_interval(std::uint64_t events, double exposure, double confidence) {
  if (!(exposure > 0.0)) throw std::invalid_argument("garwood_interval: exposure must be > 0");
  const double tail = (1.0 - confidence) / 2.0;
  const auto k = static_cast<double>(events);
  PoissonInterval interval;
  interval.low = events == 0 ? 0.0 : boost::math::gamma_p_inv(k, tail) / exposure;
  interval.high = boost::math::gamma_p_inv(k + 1.0, 1.0 - tail) / exposure;
  return interval;
}

RateEstimate estimate_rate(std::uint64_t events, double exposure) {
  RateEstimate estimate{.events = events, .exposure = exposure};
  if (events < kMinimumEvents || !(exposure > 0.0)) return estimate;
  estimate.rate = static_cast<double>(events) / exposure;
  const PoissonInterval interval = garwood_interval(events, exposure);
  estimate.low = interval.low;
  estimate.high = interval.high;
  return estimate;
}

}  // namespace swarmagg
