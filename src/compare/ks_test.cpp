#include "compare/ks_test.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace swarmagg {
namespace {

// Samples whose sizes multiply to at most this get the exact p-value (a walk over n m
// points, milliseconds); larger ones, where the asymptotic series is accurate, get that.
constexpr double kExactPairs = 1e7;

}  // namespace

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
  if (na * nb <= kExactPairs) {
    result.p_value = ks_exact_p_value(a.size(), b.size(), result.statistic);
    result.exact = true;
    return result;
  }
  const double ne = std::sqrt(na * nb / (na + nb));
  result.p_value = kolmogorov_tail((ne + 0.12 + 0.11 / ne) * result.statistic);
  return result;
}

double ks_exact_p_value(std::size_t n, std::size_t m, double statistic) {
  // D n m is a whole number (D = |i m - j n| / (n m) at some point of the walk); a walk keeps
  // D below it while |i m - j n| stays below it.
  const auto nm = static_cast<double>(n) * static_cast<double>(m);
  const double bound = std::round(statistic * nm);
  if (bound <= 0.0) return 1.0;
  const auto inside = [&](std::size_t i, std::size_t j) {
    return std::abs(static_cast<double>(i) * static_cast<double>(m) -
                    static_cast<double>(j) * static_cast<double>(n)) < bound;
  };
  // left[j]: the fraction of the C(i + j, i) walks to (i, j) that have left the band, the
  // p-value's own terms (summing those that stayed and taking 1 - their sum would cancel to 0
  // for p below 1e-16). A walk to (i, j) came from (i - 1, j) in i of every i + j cases, from
  // (i, j - 1) in j of them; one outside the band has left.
  std::vector<double> left(m + 1, 0.0);
  for (std::size_t i = 0; i <= n; ++i) {
    for (std::size_t j = 0; j <= m; ++j) {
      if (i == 0 && j == 0) {
        left[0] = 0.0;
      } else if (!inside(i, j)) {
        left[j] = 1.0;
      } else {
        const double total = static_cast<double>(i + j);
        left[j] = (i > 0 ? left[j] * static_cast<double>(i) / total : 0.0) +
                  (j > 0 ? left[j - 1] * static_cast<double>(j) / total : 0.0);
      }
    }
  }
  return std::clamp(left[m], 0.0, 1.0);
}

}  // namespace swarmagg
