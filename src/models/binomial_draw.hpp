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

// Number of successes in `trials` independent trials of probability `probability`
// (clamped to [0, 1]).
std::int64_t binomial_draw(std::int64_t trials, double probability, UniformStream& uniforms);

// The draw of binomial_draw's inversion path for the uniform u in [0, 1): the smallest k
// whose CDF exceeds u, for q <= 1/2 and a mean n q small enough that (1 - q)^n does not
// underflow (binomial_draw splits larger ones).
std::int64_t inverted_binomial(std::int64_t trials, double q, double u);

}  // namespace swarmagg
