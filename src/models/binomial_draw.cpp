#include "models/binomial_draw.hpp"

#include <cmath>

namespace swarmagg {

using binomial::kBelowFirstStepMargin;
using binomial::kLargestInvertedMean;

std::int64_t inverted_binomial(std::int64_t trials, double q, double u) {
  if (u < 1.0 - static_cast<double>(trials) * q - kBelowFirstStepMargin) return 0;
  const double odds = q / (1.0 - q);
  double probability = std::exp(static_cast<double>(trials) * std::log1p(-q));
  double cumulative = probability;
  std::int64_t successes = 0;
  while (u >= cumulative && successes < trials) {
    probability *=
        odds * static_cast<double>(trials - successes) / static_cast<double>(successes + 1);
    ++successes;
    cumulative += probability;
  }
  return successes;
}

std::int64_t binomial_draw_rest(std::int64_t trials, double probability, UniformStream& uniforms) {
  if (trials <= 0 || probability <= 0.0) return 0;
  if (probability >= 1.0) return trials;
  if (probability > 0.5) return trials - binomial_draw(trials, 1.0 - probability, uniforms);
  if (static_cast<double>(trials) * probability > kLargestInvertedMean) {
    const std::int64_t half = trials / 2;
    return binomial_draw(half, probability, uniforms) +
           binomial_draw(trials - half, probability, uniforms);
  }
  return inverted_binomial(trials, probability, uniforms.next());
}

}  // namespace swarmagg
