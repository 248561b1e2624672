#include "rates/clustered_mean.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "models/sample_statistics.hpp"
#include "synthetic_normal.hpp"

namespace swarmagg {
namespace {

using testing::standard_normal;

TEST(ClusteredMean, IsThePooledMeanWithTheClusterRobustInterval) {
  // Three replicates: values {2, 2}, {3, 3, 3}, {4, 4, 4, 4, 4}.
  const std::vector<std::vector<double>> clusters{{2, 2}, {3, 3, 3}, {4, 4, 4, 4, 4}};
  ClusteredMean mean;
  for (const auto& values : clusters) {
    double sum = 0.0;
    for (const double v : values) sum += v;
    mean.add_cluster(values.size(), sum);
  }
  const RateEstimate e = mean.estimate();
  ASSERT_TRUE(e.rate);
  EXPECT_EQ(e.events, 10u);
  EXPECT_DOUBLE_EQ(*e.rate, 3.3);
  // By hand: residual sums per cluster 4 - 6.6, 9 - 9.9, 20 - 16.5; squares 6.76 + 0.81 +
  // 12.25 = 19.82; variance 3/2 * 19.82 / 100; t at 2 degrees 4.302653.
  const double half = 4.302652729911275 * std::sqrt(1.5 * 19.82) / 10.0;
  EXPECT_NEAR(*e.low, 3.3 - half, 1e-9);
  EXPECT_NEAR(*e.high, 3.3 + half, 1e-9);

  // Merging in another grouping gives the same estimate.
  ClusteredMean first, rest;
  first.add_cluster(2, 4.0);
  rest.add_cluster(3, 9.0);
  rest.add_cluster(5, 20.0);
  first.merge(rest);
  EXPECT_DOUBLE_EQ(*first.estimate().high, *e.high);
}

TEST(ClusteredMean, TooFewObservationsOrOneReplicateGiveNoMean) {
  ClusteredMean nine;
  nine.add_cluster(5, 10.0);
  nine.add_cluster(4, 8.0);
  EXPECT_TRUE(nine.estimate().too_few());
  EXPECT_EQ(nine.estimate().events, 9u);
  ClusteredMean one_replicate;
  one_replicate.add_cluster(500, 1000.0);
  EXPECT_TRUE(one_replicate.estimate().too_few());
  ClusteredMean ten = nine;
  ten.add_cluster(1, 2.0);
  ASSERT_FALSE(ten.estimate().too_few());
  EXPECT_DOUBLE_EQ(*ten.estimate().low, 2.0);  // every value 2: no spread
  ClusteredMean empty;
  empty.add_cluster(0, 0.0);
  EXPECT_EQ(empty.clusters(), 0u);
}

// Two replicates far apart: the t interval at 1 degree (12.706 standard errors) reaches below
// 0, which no radius or rim count can; its lower end is 0.
TEST(ClusteredMean, IntervalOfTwoScatteredReplicatesStopsAtZero) {
  ClusteredMean mean;
  mean.add_cluster(5, 5.0);    // mean 1
  mean.add_cluster(5, 100.0);  // mean 20
  const RateEstimate e = mean.estimate();
  ASSERT_TRUE(e.rate);
  EXPECT_DOUBLE_EQ(*e.rate, 10.5);
  // Residual sums 5 - 52.5 and 100 - 52.5: squares 2 * 47.5^2; variance 2 * that / 100.
  const double half = 12.706204736174707 * std::sqrt(2.0 * 2.0 * 47.5 * 47.5) / 10.0;
  EXPECT_NEAR(*e.high, 10.5 + half, 1e-9);
  EXPECT_EQ(*e.low, 0.0);
}

// Replicates whose observations share a replicate effect (the same aggregate seen at
// successive recorded steps): 8 replicates of 25 observations, value = 5 + effect + noise.
// The interval treats replicates as the units, so it covers the true mean 95% +- 2% of
// 2,000 trials, where an interval over the 200 observations as independent would not.
TEST(ClusteredMean, CoversTheTrueMeanOfCorrelatedObservations) {
  constexpr int kTrials = 2000, kReplicates = 8, kObservations = 25;
  int covered = 0, naive_covered = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const CounterRng rng = CounterRng::for_replicate(77, static_cast<std::uint64_t>(trial));
    ClusteredMean mean;
    std::vector<double> all;
    for (int j = 0; j < kReplicates; ++j) {
      const double effect = standard_normal(rng, static_cast<std::uint64_t>(j), 0);
      double sum = 0.0;
      for (int i = 0; i < kObservations; ++i) {
        const double value =
            5.0 + effect +
            standard_normal(rng, static_cast<std::uint64_t>(j), static_cast<std::uint64_t>(i + 1));
        sum += value;
        all.push_back(value);
      }
      mean.add_cluster(kObservations, sum);
    }
    const RateEstimate e = mean.estimate();
    covered += *e.low <= 5.0 && 5.0 <= *e.high;
    const MeanInterval naive = mean_interval(all);
    naive_covered += std::abs(naive.mean - 5.0) <= naive.half_width;
  }
  EXPECT_NEAR(static_cast<double>(covered) / kTrials, 0.95, 0.02);
  EXPECT_LT(static_cast<double>(naive_covered) / kTrials, 0.6);
}

}  // namespace
}  // namespace swarmagg
