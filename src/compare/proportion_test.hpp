#pragma once
// The two-sample test of proportions (pooled z test) for "the two arms' escape fractions are
// equal": k_a of n_a against k_b of n_b, two-sided, normal approximation.
#include <cstdint>

namespace swarmagg {

struct ProportionResult {
  double fraction_a = 0.0;
  double fraction_b = 0.0;
  double z = 0.0;
  double p_value = 1.0;  // 1 when either arm has no trials or the pooled fraction is 0 or 1
};

ProportionResult two_proportion_test(std::int64_t k_a, std::int64_t n_a, std::int64_t k_b,
                                     std::int64_t n_b);

}  // namespace swarmagg
