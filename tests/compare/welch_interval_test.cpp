#include "compare/welch_interval.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace swarmagg {
namespace {

TEST(WelchInterval, EqualVariancesByHand) {
  // Variances 1 each, n = 3: se = sqrt(2/3) = 0.816497, dof = (2/3)^2 / (2 (1/3)^2 / 2) = 4,
  // t(0.975, 4) = 2.776445 (tables): CI = 3 +- 2.266958 (= 2.776445 * 0.816497); t = 3.674235,
  // two-sided p ~ 0.0213.
  const WelchResult w = welch_interval({1, 2, 3}, {4, 5, 6});
  EXPECT_DOUBLE_EQ(w.difference, 3.0);
  EXPECT_NEAR(w.dof, 4.0, 1e-12);
  EXPECT_NEAR(w.low, 3.0 - 2.266958, 1e-5);
  EXPECT_NEAR(w.high, 3.0 + 2.266958, 1e-5);
  EXPECT_GT(w.p_value, 0.02);
  EXPECT_LT(w.p_value, 0.0225);
}

TEST(WelchInterval, UnequalVariancesUseSatterthwaite) {
  // va = (5/3)/4 = 0.416667, vb = 10/5 = 2: dof = 2.416667^2 / (0.416667^2/3 + 2^2/4) = 5.520788.
  const WelchResult w = welch_interval({1, 2, 3, 4}, {2, 4, 6, 8, 10});
  EXPECT_NEAR(w.dof, 5.520788, 1e-5);
  EXPECT_DOUBLE_EQ(w.difference, 3.5);
  // t(0.975, 5.52) lies between the tabulated 2.4469 (dof 6) and 2.5706 (dof 5).
  const double t = (w.high - w.difference) / std::sqrt(2.416667);
  EXPECT_GT(t, 2.4469);
  EXPECT_LT(t, 2.5706);
}

TEST(WelchInterval, ConstantSamplesHaveAnExactDifference) {
  const WelchResult same = welch_interval({2, 2}, {2, 2, 2});
  EXPECT_DOUBLE_EQ(same.p_value, 1.0);
  const WelchResult apart = welch_interval({2, 2}, {5, 5});
  EXPECT_DOUBLE_EQ(apart.low, 3.0);
  EXPECT_DOUBLE_EQ(apart.p_value, 0.0);
}

TEST(MeanInterval, UsesTheStudentQuantile) {
  const MeanInterval m = mean_interval({1, 2, 3});  // sd 1, t(0.975, 2) = 4.302653
  EXPECT_DOUBLE_EQ(m.mean, 2.0);
  EXPECT_NEAR(m.half_width, 4.302653 / std::sqrt(3.0), 1e-5);
}

}  // namespace
}  // namespace swarmagg
