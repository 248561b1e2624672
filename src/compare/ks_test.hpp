#pragma once
// Two-sample Kolmogorov-Smirnov test. For samples whose sizes multiply to at most 10^7 (the
// final NOA of up to about 3,000 replicates an engine; final sizes count aggregates, so
// fewer) the p-value is exact: the share of
// the C(n + m, n) orderings of the pooled sample whose D reaches the observed one, counted by
// walking the lattice of the two empirical CDFs (Hodges 1958). Larger samples get the
// asymptotic Kolmogorov series with Stephens' correction (Numerical Recipes 14.3), which
// understates p for small ones (n = m = 3, D = 1: 0.033 where the exact p is 0.1). Both
// assume no ties; with ties (discrete data such as NOA) D can only be smaller, so the exact
// p-value is conservative: too large, never too small.
#include <cstddef>
#include <vector>

namespace swarmagg {

struct KsResult {
  double statistic = 0.0;  // D, the largest distance between the two empirical CDFs
  double p_value = 1.0;
  int n_a = 0;
  int n_b = 0;
  bool exact = false;  // the p-value from the lattice walk, not the asymptotic series
};

KsResult ks_two_sample(std::vector<double> a, std::vector<double> b);
// P(D >= statistic) for samples of n and m distinct values under the null hypothesis.
double ks_exact_p_value(std::size_t n, std::size_t m, double statistic);
// Q_KS(lambda) = 2 sum_{j>=1} (-1)^(j-1) exp(-2 j^2 lambda^2), clamped to [0, 1].
double kolmogorov_tail(double lambda);

}  // namespace swarmagg
