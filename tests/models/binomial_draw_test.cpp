#include "models/binomial_draw.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace swarmagg {
namespace {

struct Moments {
  double mean = 0.0, variance = 0.0;
};

Moments draw_moments(std::int64_t trials, double q, int draws) {
  const CounterRng rng = CounterRng::for_replicate(7, 0);
  double sum = 0.0, squares = 0.0;
  for (int i = 0; i < draws; ++i) {
    UniformStream uniforms(rng, static_cast<std::uint64_t>(i), 0);
    const auto x = static_cast<double>(binomial_draw(trials, q, uniforms));
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, static_cast<double>(trials));
    sum += x;
    squares += x * x;
  }
  const double mean = sum / draws;
  return {mean, squares / draws - mean * mean};
}

// Mean within 5 standard errors of nq, variance within 10% of nq(1-q).
void expect_binomial(std::int64_t trials, double q) {
  const int draws = 40000;
  const Moments moments = draw_moments(trials, q, draws);
  const double variance = trials * q * (1 - q);
  EXPECT_NEAR(moments.mean, trials * q, 5 * std::sqrt(variance / draws)) << trials << " " << q;
  EXPECT_NEAR(moments.variance / variance, 1.0, 0.1) << trials << " " << q;
}

TEST(BinomialDraw, InvertedSplitAndMirroredPathsHaveBinomialMoments) {
  expect_binomial(10, 0.3);     // inversion
  expect_binomial(2, 0.01);     // rare events
  expect_binomial(1000, 0.05);  // mean 50: split into halves
  expect_binomial(50, 0.9);     // mirrored: 50 - Binomial(50, 0.1)
  expect_binomial(5000, 0.5);   // deep split
}

TEST(BinomialDraw, EdgeCases) {
  UniformStream uniforms(CounterRng::for_replicate(1, 0), 0, 0);
  EXPECT_EQ(binomial_draw(0, 0.5, uniforms), 0);
  EXPECT_EQ(binomial_draw(10, 0.0, uniforms), 0);
  EXPECT_EQ(binomial_draw(10, 1.0, uniforms), 10);
  EXPECT_EQ(binomial_draw(10, 1.5, uniforms), 10);
}

TEST(BinomialDraw, IsAPureFunctionOfKeyStepAndStream) {
  const CounterRng rng = CounterRng::for_replicate(3, 1);
  std::vector<std::int64_t> first, again, other_stream;
  for (std::uint64_t step = 0; step < 200; ++step) {
    UniformStream a(rng, step, 0), b(rng, step, 0), c(rng, step, 1);
    first.push_back(binomial_draw(100, 0.2, a));
    again.push_back(binomial_draw(100, 0.2, b));
    other_stream.push_back(binomial_draw(100, 0.2, c));
  }
  EXPECT_EQ(first, again);
  EXPECT_NE(first, other_stream);
}

}  // namespace
}  // namespace swarmagg
