#pragma once
// A rate measured as events over exposure (docs/models.md). Given the exposure, the event count is
// Poisson, so the 95% interval is the exact (Garwood) one: the rate whose Poisson
// distribution puts 2.5% above (below) the count, from the gamma quantiles
//   low = Q_gamma(k, 0.025) / E (0 for k = 0),  high = Q_gamma(k + 1, 0.975) / E.
// It covers the true rate with probability at least 95% for any rate. Fewer than
// kMinimumEvents events give no rate at all: an estimate from a handful of events is noise,
// and the outputs say "too few" rather than print it.
#include <cstdint>
#include <optional>

namespace swarmagg {

inline constexpr std::uint64_t kMinimumEvents = 10;

struct RateEstimate {
  std::uint64_t events = 0;
  double exposure = 0.0;            // the unit the rate is per (pair-tu, searcher-aggregate-tu ...)
  std::optional<double> rate = {};  // events / exposure; empty when too few events
  std::optional<double> low = {}, high = {};
  bool too_few() const { return !rate; }
};

// The exact interval of confidence `confidence` for `events` over `exposure` (> 0), whatever
// the count.
struct PoissonInterval {
  double low = 0.0;
  double high = 0.0;
};
PoissonInterval garwood_interval(std::uint64_t events, double exposure, double confidence = 0.95);

// The reported estimate: rate and 95% interval only from kMinimumEvents events on.
RateEstimate estimate_rate(std::uint64_t events, double exposure);

}  // namespace swarmagg
