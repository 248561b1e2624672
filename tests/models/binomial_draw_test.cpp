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

namespace swarmagg {
namespace {

// The CDF inversion written out in full, without the shortcut for uniforms below
// 1 - n q: the draws must be the same whatever the shortcut decides.
std::int64_t fully_inverted(std::int64_t trials, double q, double u) {
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

TEST(BinomialDraw, NoSuccessShortcutDrawsWhatFullInversionDraws) {
  const CounterRng rng = CounterRng::for_replicate(11, 0);
  int shortcut_region = 0;
  for (std::uint64_t step = 0; step < 20000; ++step) {
    UniformStream parameters(rng, step, 1);
    const auto trials = static_cast<std::int64_t>(1 + 40 * parameters.next());
    // Small probabilities, as a model's per-step rates are, and some near the mean of 20.
    const double q = std::pow(10.0, -6.0 * parameters.next()) * (step % 2 ? 0.5 : 0.01);
    if (static_cast<double>(trials) * q > 20.0) continue;
    UniformStream drawn(rng, step, 0), reference(rng, step, 0);
    const double u = reference.next();
    shortcut_region += u < 1.0 - static_cast<double>(trials) * q ? 1 : 0;
    ASSERT_EQ(binomial_draw(trials, q, drawn), fully_inverted(trials, q, u))
        << trials << " trials, q " << q << ", u " << u;
  }
  EXPECT_GT(shortcut_region, 1000);  // the shortcut was exercised, not only the full walk
}

// Uniforms right at the edge of the shortcut, 1 - n q less its margin, and around it.
TEST(BinomialDraw, NoSuccessShortcutHoldsAtItsEdge) {
  for (const double q : {1e-9, 1e-6, 1e-4, 0.01, 0.1, 0.5}) {
    for (const std::int64_t trials : {1, 2, 7, 30}) {
      if (static_cast<double>(trials) * q > 20.0) continue;
      const double edge = 1.0 - static_cast<double>(trials) * q;
      for (const double offset : {-1e-6, -2e-9, -1e-9, -5e-10, 0.0, 1e-12, 1e-9, 1e-3}) {
        const double u = edge + offset;
        if (u < 0.0 || u >= 1.0) continue;
        EXPECT_EQ(inverted_binomial(trials, q, u), fully_inverted(trials, q, u))
            << trials << " trials, q " << q << ", u " << u;
      }
    }
  }
}

// binomial_draw decides most draws on its short path and hands the rest to
// binomial_draw_rest, which takes every case: both must draw the same counts from the same
// uniforms, and use the same number of them (the next uniform of each stream agrees).
TEST(BinomialDraw, ShortPathDrawsWhatTheGeneralPathDraws) {
  const CounterRng rng = CounterRng::for_replicate(5, 2);
  for (std::uint64_t step = 0; step < 20000; ++step) {
    UniformStream parameters(rng, step, 1);
    const auto trials = static_cast<std::int64_t>(200 * parameters.next()) - 5;
    const double q = step % 3 == 0 ? parameters.next() : std::pow(10.0, -5.0 * parameters.next());
    UniformStream short_path(rng, step, 0), general(rng, step, 0);
    ASSERT_EQ(binomial_draw(trials, q, short_path), binomial_draw_rest(trials, q, general))
        << trials << " trials, q " << q;
    ASSERT_EQ(short_path.next(), general.next()) << trials << " trials, q " << q;
  }
  for (const double q : {std::nan(""), -0.0, 0.0, 0.5, 1.0, 2.0, 1e-300}) {
    UniformStream short_path(rng, 0, 2), general(rng, 0, 2);
    ASSERT_EQ(binomial_draw(7, q, short_path), binomial_draw_rest(7, q, general)) << q;
    ASSERT_EQ(short_path.next(), general.next()) << q;
  }
}

}  // namespace
}  // namespace swarmagg
