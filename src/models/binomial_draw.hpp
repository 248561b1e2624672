#pragma once
// Binomial variates from the counter-based generator, so a stochastic model run is a pure
// function of (seed, replicate, step): a UniformStream hands out the uniforms of one step of
// one stream in order, and binomial_draw is exact (inversion of the CDF) and portable,
// unlike std::binomial_distribution whose algorithm the standard library chooses.
#include <cstdint>

#include "core/rng.hpp"

namespace swarmagg {

class UniformStream {
 public:
  // The step's share of the hash is done once: a model step draws several uniforms.
  UniformStream(const CounterRng& rng, std::uint64_t step, std::uint64_t stream)
      : step_rng_(rng.at_step(step)), stream_(stream) {}
  double next() { return step_rng_.uniform(drawn_++, Draw::Model, stream_); }

 private:
  StepRng step_rng_;
  std::uint64_t stream_;
  std::uint64_t drawn_ = 0;
};

namespace binomial {
// Inversion walks the CDF from 0, which takes about trials * probability iterations and
// needs P(0) = (1 - q)^n to stay far from underflow; above this mean the trials are split
// in two halves (the sum of independent binomials with the same q is binomial).
inline constexpr double kLargestInvertedMean = 20.0;
// P(0) = (1 - q)^n >= 1 - n q (Bernoulli's inequality), and exp(n log1p(-q)) is within a
// few ulp of it, so a uniform below 1 - n q less this margin (far above rounding) is below
// the computed P(0) too: no success, known without the exp and log1p that most draws of a
// model's small per-step probabilities would otherwise cost.
inline constexpr double kBelowFirstStepMargin = 1e-9;
}  // namespace binomial

// The draw of binomial_draw's inversion path for the uniform u in [0, 1): the smallest k
// whose CDF exceeds u, for q <= 1/2 and a mean n q small enough that (1 - q)^n does not
// underflow (binomial_draw_rest splits larger ones).
std::int64_t inverted_binomial(std::int64_t trials, double q, double u);

// binomial_draw for the cases the inline part leaves: no trials, probabilities out of
// (0, 1/2] and large means.
std::int64_t binomial_draw_rest(std::int64_t trials, double probability, UniformStream& uniforms);

// Number of successes in `trials` independent trials of probability `probability`
// (clamped to [0, 1]). A stochastic model run draws billions of these, nearly all with a
// small probability and no success: that case takes a short path with nothing to save on
// the stack, one uniform and one comparison (the same as inverted_binomial's first); the
// others, which may recurse, go to binomial_draw_rest. The draws are those of
// binomial_draw_rest alone (docs/performance.md, "Stores that hold up reads").
inline std::int64_t binomial_draw(std::int64_t trials, double probability,
                                  UniformStream& uniforms) {
  const double mean = static_cast<double>(trials) * probability;
  if (trials <= 0 || !(probability > 0.0) || probability > 0.5 ||
      mean > binomial::kLargestInvertedMean) {
    return binomial_draw_rest(trials, probability, uniforms);
  }
  const double u = uniforms.next();
  if (u < 1.0 - mean - binomial::kBelowFirstStepMargin) return 0;
  return inverted_binomial(trials, probability, u);
}

}  // namespace swarmagg
