#include "compare/ks_test.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(KolmogorovTail, MatchesTheClassicFivePercentPoint) {
  // The tabulated large-sample 5% critical value of sqrt(ne) D is 1.3581.
  EXPECT_NEAR(kolmogorov_tail(1.3581), 0.05, 1e-4);
  EXPECT_DOUBLE_EQ(kolmogorov_tail(0.0), 1.0);
  EXPECT_LT(kolmogorov_tail(3.0), 1e-6);
}

TEST(KsTwoSample, StatisticAndPValueByHand) {
  // CDFs at 5: a = 5/5, b = 2/6, ... the largest gap is at 5: 1 - 3/6 = 0.5.
  // ne = 5*6/11; lambda = (sqrt(ne) + 0.12 + 0.11/sqrt(ne)) * 0.5 = 0.919027;
  // Q_KS(0.919027) = 0.367001 (series summed by hand in Python).
  const KsResult ks = ks_two_sample({5, 1, 3, 2, 4}, {3, 4, 5, 6, 7, 8});
  EXPECT_DOUBLE_EQ(ks.statistic, 0.5);
  EXPECT_NEAR(ks.p_value, 0.367001, 1e-6);
  EXPECT_EQ(ks.n_a, 5);
  EXPECT_EQ(ks.n_b, 6);
}

TEST(KsTwoSample, TiesDoNotInflateTheStatistic) {
  const KsResult same = ks_two_sample({2, 2, 3, 3}, {3, 2, 3, 2});
  EXPECT_DOUBLE_EQ(same.statistic, 0.0);
  EXPECT_DOUBLE_EQ(same.p_value, 1.0);
  // Both step at 1; only after 2 do they part: a = 3/4, b = 1/4.
  EXPECT_DOUBLE_EQ(ks_two_sample({1, 2, 2, 3}, {1, 3, 3, 3}).statistic, 0.5);
}

TEST(KsTwoSample, SeparatedSamplesAreSignificant) {
  std::vector<double> a, b;
  for (int i = 0; i < 20; ++i) {
    a.push_back(i);
    b.push_back(100 + i);
  }
  const KsResult ks = ks_two_sample(a, b);
  EXPECT_DOUBLE_EQ(ks.statistic, 1.0);
  EXPECT_LT(ks.p_value, 1e-6);
}

}  // namespace
}  // namespace swarmagg
