#include "rates/power_law_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "synthetic_normal.hpp"

namespace swarmagg {
namespace {

using testing::standard_normal;

TEST(PowerLawFit, RecoversAnExactPowerLaw) {
  std::vector<PowerLawPoint> points;
  for (const int m : {2, 3, 5, 8, 13, 21})
    points.push_back({double(m), 1.2 * std::pow(m, 0.48), 1.0 + m});
  const PowerLawFit fit = fit_power_law(points);
  ASSERT_TRUE(fit.fitted());
  EXPECT_EQ(fit.sizes, 6);
  EXPECT_NEAR(fit.a->value, 1.2, 1e-12);
  EXPECT_NEAR(fit.b->value, 0.48, 1e-12);
  EXPECT_NEAR(fit.b->high - fit.b->low, 0.0, 1e-9);  // no residual, no width
}

// Data from known a = 1.7, b = 0.41 with log-normal scatter whose variance falls as
// 1 / observations (a mean over n observations), weighted by observations: the fitted
// interval covers the true a and b, and does so in 95% +- 2% of 2,000 trials.
TEST(PowerLawFit, IntervalsCoverTheTrueLawOnSyntheticData) {
  constexpr double kA = 1.7, kB = 0.41;
  const std::vector<int> sizes{2, 3, 4, 6, 9, 14, 20, 30};
  constexpr int kTrials = 2000;
  int a_covered = 0, b_covered = 0;
  double b_sum = 0.0;
  for (int trial = 0; trial < kTrials; ++trial) {
    const CounterRng rng = CounterRng::for_replicate(5, static_cast<std::uint64_t>(trial));
    std::vector<PowerLawPoint> points;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      const double observations = 400.0 / sizes[i];  // large aggregates are seen less often
      const double noise = 0.3 / std::sqrt(observations) * standard_normal(rng, i, 0);
      points.push_back(
          {double(sizes[i]), kA * std::pow(sizes[i], kB) * std::exp(noise), observations});
    }
    const PowerLawFit fit = fit_power_law(points);
    ASSERT_TRUE(fit.fitted());
    a_covered += fit.a->covers(kA);
    b_covered += fit.b->covers(kB);
    b_sum += fit.b->value;
    if (trial == 0) {
      EXPECT_TRUE(fit.a->covers(kA));
      EXPECT_TRUE(fit.b->covers(kB));
    }
  }
  EXPECT_NEAR(b_sum / kTrials, kB, 0.002);
  EXPECT_NEAR(static_cast<double>(a_covered) / kTrials, 0.95, 0.02);
  EXPECT_NEAR(static_cast<double>(b_covered) / kTrials, 0.95, 0.02);
}

TEST(PowerLawFit, RefusesFewerThanThreeSizes) {
  const std::vector<PowerLawPoint> two{{2.0, 1.5, 10.0}, {3.0, 1.9, 10.0}};
  const PowerLawFit fit = fit_power_law(two);
  EXPECT_FALSE(fit.fitted());
  EXPECT_FALSE(fit.a);
  EXPECT_NE(fit.refused.find("2 size(s)"), std::string::npos) << fit.refused;
  // Three points but two distinct sizes: still no fit.
  const std::vector<PowerLawPoint> repeated{{2.0, 1.5, 1.0}, {2.0, 1.6, 1.0}, {3.0, 1.9, 1.0}};
  EXPECT_FALSE(fit_power_law(repeated).fitted());
  EXPECT_FALSE(fit_power_law({}).fitted());
  const std::vector<PowerLawPoint> zero{{2.0, 0.0, 1.0}, {3.0, 1.0, 1.0}, {4.0, 1.0, 1.0}};
  EXPECT_THROW(fit_power_law(zero), std::invalid_argument);
}

}  // namespace
}  // namespace swarmagg
