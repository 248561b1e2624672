// Long curves are drawn from evenly spaced points within a limit, always with their ends.
#include "plot/drawn_points.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(DrawnPoints, ACurveWithinTheLimitIsDrawnWhole) {
  for (const std::size_t count : {std::size_t{1}, std::size_t{7}, kMostDrawnPoints}) {
    const std::vector<std::size_t> indices = drawn_indices(count);
    ASSERT_EQ(indices.size(), count);
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(indices[i], i);
  }
  EXPECT_TRUE(drawn_indices(0).empty());
}

// 10^6 + 1 points (10^7 steps recorded every 10, and step 0): every 101st (every 100th would
// give 10,001) and the last.
TEST(DrawnPoints, ALongerCurveKeepsEveryKthPointAndTheLastWithinTheLimit) {
  const std::vector<std::size_t> indices = drawn_indices(1'000'001);
  ASSERT_LE(indices.size(), kMostDrawnPoints);
  EXPECT_EQ(indices.size(), 9902u);  // 0, 101, ..., 999,900, then 1,000,000
  EXPECT_EQ(indices[1], 101u);
  EXPECT_EQ(indices[indices.size() - 2], 999'900u);
  EXPECT_EQ(indices.back(), 1'000'000u);
  for (const std::size_t count : {kMostDrawnPoints + 1, 2 * kMostDrawnPoints + 1}) {
    const std::vector<std::size_t> some = drawn_indices(count);
    EXPECT_LE(some.size(), kMostDrawnPoints) << count;
    EXPECT_GT(some.size(), kMostDrawnPoints / 2) << count;
    EXPECT_EQ(some.front(), 0u);
    EXPECT_EQ(some.back(), count - 1) << count;
  }
}

TEST(DrawnPoints, SeriesAndCurvesKeepTheSamePoints) {
  StepSeries series;
  ModelCurve curve{"original", {}, {}};
  for (int i = 0; i < 25'000; ++i) {
    series.steps.push_back(10 * i);
    series.times.push_back(i);
    series.values.push_back({static_cast<double>(i), 2.0 * i});
    curve.x.push_back(i);
    curve.y.push_back(3.0 * i);
  }
  const StepSeries drawn = drawn_part(series);
  const std::vector<ModelCurve> drawn_curves = drawn_part(std::vector<ModelCurve>{curve});
  ASSERT_EQ(drawn_curves.size(), 1u);
  EXPECT_EQ(drawn_curves[0].variant, "original");
  ASSERT_EQ(drawn.steps.size(), drawn_curves[0].x.size());
  for (std::size_t i = 0; i < drawn.steps.size(); ++i) {
    EXPECT_EQ(drawn.steps[i], 10 * static_cast<std::int64_t>(drawn.times[i]));
    EXPECT_EQ(drawn.values[i][1], 2.0 * drawn.times[i]);
    EXPECT_EQ(drawn_curves[0].x[i], drawn.times[i]);
    EXPECT_EQ(drawn_curves[0].y[i], 3.0 * drawn.times[i]);
  }
  EXPECT_EQ(drawn.times.back(), 24'999.0);
}

}  // namespace
}  // namespace swarmagg
