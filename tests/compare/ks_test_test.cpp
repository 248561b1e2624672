#include "compare/ks_test.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace swarmagg {
namespace {

TEST(KolmogorovTail, MatchesTheClassicFivePercentPoint) {
  // The tabulated large-sample 5% critical value of sqrt(ne) D is 1.3581.
  EXPECT_NEAR(kolmogorov_tail(1.3581), 0.05, 1e-4);
  EXPECT_DOUBLE_EQ(kolmogorov_tail(0.0), 1.0);
  EXPECT_LT(kolmogorov_tail(3.0), 1e-6);
}

TEST(KsTwoSample, StatisticAndExactPValueByHand) {
  // CDFs at 5: a = 5/5, b = 2/6, ... the largest gap is at 5: 1 - 3/6 = 0.5. Of the
  // C(11, 5) = 462 orderings of 11 distinct values, 165 reach D >= 1/2 (enumerated in Python;
  // scipy.stats.ks_2samp(method='exact') agrees).
  const KsResult ks = ks_two_sample({5, 1, 3, 2, 4}, {3, 4, 5, 6, 7, 8});
  EXPECT_DOUBLE_EQ(ks.statistic, 0.5);
  EXPECT_NEAR(ks.p_value, 165.0 / 462.0, 1e-12);
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

// Three replicates an engine, all apart: only the 2 of the C(6, 3) = 20 orderings that keep
// the samples apart reach D = 1, so p = 0.1, not significant (the asymptotic series said
// 0.033). Two against two: 2 / 6.
TEST(KsTwoSample, SmallSamplesGetTheExactPValue) {
  EXPECT_NEAR(ks_two_sample({2, 2, 2}, {0, 0, 0}).p_value, 0.1, 1e-12);
  EXPECT_NEAR(ks_two_sample({1, 2, 3}, {4, 5, 6}).p_value, 0.1, 1e-12);
  EXPECT_NEAR(ks_two_sample({1, 2}, {3, 4}).p_value, 1.0 / 3.0, 1e-12);
  // Four against four, D = 1: 2 / 70.
  EXPECT_NEAR(ks_two_sample({1, 2, 3, 4}, {5, 6, 7, 8}).p_value, 2.0 / 70.0, 1e-12);
}

// A larger case against scipy.stats.ks_2samp(method='exact') (scipy 1.10): 0..99 against
// 19..118, D = 0.19, p = 0.05390207893129876; the asymptotic series is within 0.01 of it.
TEST(KsExactPValue, MatchesScipyForALargerSample) {
  const double exact = ks_exact_p_value(100, 100, 0.19);
  EXPECT_NEAR(exact, 0.05390207893129876, 1e-9);
  const double ne = std::sqrt(100.0 * 100.0 / 200.0);
  EXPECT_NEAR(exact, kolmogorov_tail((ne + 0.12 + 0.11 / ne) * 0.19), 0.01);
  EXPECT_DOUBLE_EQ(ks_exact_p_value(5, 7, 0.0), 1.0);
}

// Under the null hypothesis a 5 % test rejects at most 5 % of the time. The asymptotic
// series rejected 10 % of pairs of 3 uniform samples, 8 % of pairs of 5 or 8 (20,000 pairs
// each); the exact p-values reject 0, 0.8 and 1.7 %.
// Tiny p-values keep their relative precision (scipy 1.10's exact method gives these; one
// minus the share of walks that stayed inside gave 0 for both). 5 against 7 all apart:
// 2 / C(12, 5).
TEST(KsExactPValue, TinyPValuesAreNotRoundedToZero) {
  EXPECT_NEAR(ks_exact_p_value(100, 100, 0.6) / 4.528308394643339e-17, 1.0, 1e-9);
  EXPECT_NEAR(ks_exact_p_value(100, 100, 1.0) / 2.2087606931995054e-59, 1.0, 1e-9);
  EXPECT_NEAR(ks_exact_p_value(5, 7, 1.0), 2.0 / 792.0, 1e-15);
}

// Past 10^7 pairs of values the asymptotic series takes over (and says so).
TEST(KsTwoSample, LargeSamplesUseTheAsymptoticSeries) {
  std::vector<double> a(3200), b(3200);
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = static_cast<double>(i);
    b[i] = static_cast<double>(i) + 100.0;  // D = 100 / 3200
  }
  const KsResult ks = ks_two_sample(a, b);
  EXPECT_FALSE(ks.exact);
  EXPECT_NEAR(ks.statistic, 100.0 / 3200.0, 1e-12);
  const double ne = std::sqrt(3200.0 * 3200.0 / 6400.0);
  EXPECT_DOUBLE_EQ(ks.p_value, kolmogorov_tail((ne + 0.12 + 0.11 / ne) * ks.statistic));
  EXPECT_TRUE(ks_two_sample({1, 2}, {3, 4}).exact);
}

TEST(KsTwoSample, ATrueNullIsRejectedAtMostAtTheTestsLevel) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform;
  for (const int n : {3, 5, 8}) {
    int rejected = 0;
    const int pairs = 4000;
    for (int t = 0; t < pairs; ++t) {
      std::vector<double> a(static_cast<std::size_t>(n)), b(static_cast<std::size_t>(n));
      for (double& x : a) x = uniform(rng);
      for (double& x : b) x = uniform(rng);
      rejected += ks_two_sample(a, b).p_value < 0.05;
    }
    EXPECT_LE(rejected, pairs / 20) << n << " values a sample";
  }
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
