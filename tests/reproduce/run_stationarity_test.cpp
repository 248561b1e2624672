#include "analysis/run_stationarity.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

// Three replicates over 100 tu; NOA per replicate given by `noa(replicate, time)`.
template <typename Noa>
StepSeries series(Noa noa) {
  StepSeries s;
  for (int k = 0; k <= 100; ++k) {
    s.steps.push_back(k);
    s.times.push_back(0.1 * 3.0 * k);  // 0.3 tu apart: times that do not sum exactly
    s.values.push_back({noa(0, k), noa(1, k), noa(2, k)});
  }
  return s;
}

TEST(RunStationarity, AFlatRunIsStationary) {
  const NoaTrend t = second_half_trend(series([](int r, int) { return 3.0 + r; }));
  EXPECT_NEAR(t.change, 0.0, 1e-9);
  EXPECT_TRUE(t.stationary());
}

// A run whose replicates all froze shows no trend, as a mixing one does; it is told apart by
// counting the replicates whose NOA kept one value over the second half.
TEST(RunStationarity, CountsTheReplicatesThatFroze) {
  const NoaTrend frozen = second_half_trend(series([](int r, int) { return 3.0 + r; }));
  EXPECT_EQ(frozen.frozen, 3);
  EXPECT_EQ(frozen.replicates, 3);
  // Replicate 1 alternates over the second half; the others change only in the first.
  const NoaTrend mixing = second_half_trend(
      series([](int r, int k) { return r == 1 ? 3.0 + (k % 2) : (k < 50 ? 5.0 : 4.0); }));
  EXPECT_TRUE(mixing.stationary());
  EXPECT_EQ(mixing.frozen, 2);
}

TEST(RunStationarity, ARunStillMergingTrends) {
  // Every replicate loses one aggregate per 30 tu over the second half (50 steps of 0.3 tu).
  const NoaTrend t = second_half_trend(
      series([](int r, int k) { return 10.0 + r - k / 100.0 * 10.0 + 0.01 * r * (k % 2); }));
  EXPECT_NEAR(t.change, -5.0, 0.05);
  EXPECT_FALSE(t.stationary());
}

TEST(RunStationarity, DistributionIsTheShareOfRecordedSteps) {
  const auto d = value_distribution(series([](int r, int) { return r == 0 ? 1.0 : 2.0; }));
  ASSERT_EQ(d.size(), 2u);
  EXPECT_NEAR(d.at(1), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(d.at(2), 2.0 / 3.0, 1e-12);
}

}  // namespace
}  // namespace swarmagg
