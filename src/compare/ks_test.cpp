#include "compare/ks_test.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {

double kolmogorov_tail(double lambda) {
  // The series converges badly near 0, where the tail is 1 to double precision anyway.
  if (lambda < 0.2) return 1.0;
  double sum = 0.0;
  double sign = 1.0;
  for (int j = 1; j <= 100; ++j) {
    const double term = sign * std::exp(-2.0 * j * j * lambda * lambda);
    sum += term;
    if (std::abs(term) < 1e-16 * std::abs(sum)) break;
    sign = -sign;
  }
  return std::clamp(2.0 * sum, 0.0, 1.0);
}

KsResult ks_two_sample(std::vector<double> a, std::vector<double> b) {
  KsResult result;
  result.n_a = static_cast<int>(a.size());
  result.n_b = static_cast<int>(b.size());
  if (a.empty() || b.empty()) return result;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  const double na = static_cast<double>(a.size());
  const double nb = static_cast<double>(b.size());
  std::size_t i = 0;
  std::size_t j = 0;
  // Walk both sorted samples together; at each distinct value both CDFs step past all
  // of its copies before they are compared, so ties never inflate D.
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] == x) ++i;
    while (j < b.size() && b[j] == x) ++j;
    result.statistic = std::max(result.statistic, std::abs(i / na - j / nb));
  }
  const double ne = std::sqrt(na * nb / (na + nb));
  result.p_value = kolmogorov_tail((ne + 0.12 + 0.11 / ne) * result.statistic);
  return result;
}

}  // namespace swarmagg
