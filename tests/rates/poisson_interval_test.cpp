#include "rates/poisson_interval.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"

namespace swarmagg {
namespace {

// Events of a Poisson process of rate `rate` over `exposure`: exponential gaps drawn from
// the counter generator (stream `trial`), so every trial is reproducible.
std::uint64_t poisson_stream(double rate, double exposure, std::uint64_t trial) {
  const CounterRng rng = CounterRng::for_replicate(2024, trial);
  double time = 0.0;
  std::uint64_t events = 0;
  for (std::uint64_t k = 0;; ++k) {
    time += -std::log(1.0 - rng.uniform(k, 0, Draw::Model)) / rate;
    if (time > exposure) return events;
    ++events;
  }
}

double coverage(double rate, double exposure) {
  constexpr int kTrials = 2000;
  int covered = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const std::uint64_t events = poisson_stream(rate, exposure, static_cast<std::uint64_t>(trial));
    const PoissonInterval interval = garwood_interval(events, exposure);
    covered += interval.low <= rate && rate <= interval.high;
  }
  return static_cast<double>(covered) / kTrials;
}

TEST(PoissonInterval, CoversTheTrueRateIn95PercentOfSyntheticStreams) {
  // Expected counts of 15, 40 and 200 events: the exact interval is conservative by at most
  // a little at these counts, so 95% +- 2% holds.
  EXPECT_NEAR(coverage(0.003, 5000.0), 0.95, 0.02);
  EXPECT_NEAR(coverage(2.0, 20.0), 0.95, 0.02);
  EXPECT_NEAR(coverage(0.5, 400.0), 0.95, 0.02);
}

TEST(PoissonInterval, MatchesTheGammaQuantilesOfKnownCounts) {
  // Garwood's table: k = 0 -> [0, 3.689]; k = 10 -> [4.795, 18.39] (per unit exposure).
  const PoissonInterval zero = garwood_interval(0, 1.0);
  EXPECT_EQ(zero.low, 0.0);
  EXPECT_NEAR(zero.high, 3.689, 1e-3);
  const PoissonInterval ten = garwood_interval(10, 2.0);
  EXPECT_NEAR(ten.low, 4.795 / 2.0, 1e-3);
  EXPECT_NEAR(ten.high, 18.39 / 2.0, 1e-2);
}

TEST(PoissonInterval, FewerThanTenEventsGiveNoRate) {
  const RateEstimate nine = estimate_rate(9, 3.0);
  EXPECT_TRUE(nine.too_few());
  EXPECT_FALSE(nine.low);
  EXPECT_EQ(nine.events, 9u);
  const RateEstimate ten = estimate_rate(10, 4.0);
  ASSERT_FALSE(ten.too_few());
  EXPECT_DOUBLE_EQ(*ten.rate, 2.5);
  EXPECT_LT(*ten.low, 2.5);
  EXPECT_GT(*ten.high, 2.5);
  EXPECT_TRUE(estimate_rate(50, 0.0).too_few());
}

}  // namespace
}  // namespace swarmagg
