#include "analysis/replicate_spread.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace swarmagg {
namespace {

// Two replicates, a and b: a resample draws aa, ab, ba or bb alike, so its mean lies |a - b| / 2
// from the sample's half the time and on it otherwise: |a - b| / 4, times sqrt(2 / 1).
TEST(ReplicateSpread, TwoReplicatesSpreadAQuarterOfTheirDifference) {
  NoaSeries series;
  series.steps = {0, 10};
  series.times = {0.0, 1.0};
  series.values = {{0.0, 4.0}, {2.0, 6.0}};
  EXPECT_NEAR(noa_spread(series), std::sqrt(2.0), 0.07);
  EXPECT_EQ(noa_spread(series), noa_spread(series));  // the same resamples every time
  const std::vector<Distribution> disjoint{{{"5", 1.0}}, {{"4+1", 1.0}}};
  EXPECT_NEAR(partition_spread(disjoint), 0.25 * std::sqrt(2.0), 0.03);
}

TEST(ReplicateSpread, AlikeOrSingleReplicatesHaveNone) {
  NoaSeries same;
  same.steps = {0};
  same.times = {0.0};
  same.values = {{3.0, 3.0, 3.0}};
  EXPECT_EQ(noa_spread(same), 0.0);
  same.values = {{3.0}};
  EXPECT_EQ(noa_spread(same), 0.0);
  EXPECT_EQ(partition_spread({{{"3+2", 0.6}, {"5", 0.4}}, {{"3+2", 0.6}, {"5", 0.4}}}), 0.0);
  EXPECT_EQ(partition_spread({{{"5", 1.0}}}), 0.0);
}

TEST(ReplicateSpread, ResamplesDrawEveryReplicateAlike) {
  std::vector<int> drawn(10, 0);
  for (int b = 0; b < kSpreadResamples; ++b) {
    for (std::size_t k = 0; k < 10; ++k) ++drawn[resampled_replicate(b, k, 10)];
  }
  for (const int count : drawn) EXPECT_NEAR(count, kSpreadResamples, 0.1 * kSpreadResamples);
}

}  // namespace
}  // namespace swarmagg
