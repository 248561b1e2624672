#pragma once
// Two-sample Kolmogorov-Smirnov test. Boost.Math 1.74 (Debian) has no Kolmogorov
// distribution, so the p-value is the asymptotic Kolmogorov series with Stephens'
// small-sample correction (Numerical Recipes 14.3): lambda = (sqrt(ne) + 0.12 +
// 0.11 / sqrt(ne)) D with ne = n m / (n + m). With ties (discrete data such as NOA) the
// test is conservative: the p-value is too large, never too small.
#include <vector>

namespace swarmagg {

struct KsResult {
  double statistic = 0.0;  // D, the largest distance between the two empirical CDFs
  double p_value = 1.0;
  int n_a = 0;
  int n_b = 0;
};

KsResult ks_two_sample(std::vector<double> a, std::vector<double> b);
// Q_KS(lambda) = 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 lambda^2), clamped to [0, 1].
double kolmogorov_tail(double lambda);

}  // namespace swarmagg
