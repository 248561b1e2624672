#include "compare/proportion_test.hpp"

#include <cmath>

namespace swarmagg {

ProportionResult two_proportion_test(std::int64_t k_a, std::int64_t n_a, std::int64_t k_b,
                                     std::int64_t n_b) {
  ProportionResult r;
  if (n_a <= 0 || n_b <= 0) return r;
  const double na = static_cast<double>(n_a);
  const double nb = static_cast<double>(n_b);
  r.fraction_a = static_cast<double>(k_a) / na;
  r.fraction_b = static_cast<double>(k_b) / nb;
  const double pooled = static_cast<double>(k_a + k_b) / (na + nb);
  const double variance = pooled * (1.0 - pooled) * (1.0 / na + 1.0 / nb);
  if (!(variance > 0.0)) return r;
  r.z = (r.fraction_b - r.fraction_a) / std::sqrt(variance);
  r.p_value = std::erfc(std::fabs(r.z) / std::sqrt(2.0));
  return r;
}

}  // namespace swarmagg
