#include "models/bayindir_expected.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

BayindirState run_steps(const BayindirRates& rates, std::int64_t steps) {
  BayindirState state = BayindirState::all_searching(rates.agents);
  for (std::int64_t i = 0; i < steps; ++i) advance_expected(rates, state);
  return state;
}

// The difference equation y' = y - 2k y^2 is the forward-Euler step (one step of dt) of
// dy/dt = -2k y^2, whose solution is y = N / (1 + 2kNt). Euler's error: 1/y_{t+1} =
// 1/y_t + 2k + 4k^2 y_t + ..., so 1/y_t exceeds the closed form by about
// 2k ln(1 + 2kNt), a relative error of 2kN ln(1+x)/(1+x) <= 2kN/e (x = 2kNt).
double euler_tolerance(double k, int agents) {
  return 1.1 * 2.0 * k * agents / std::exp(1.0);
}

TEST(BayindirExpected, CreationOnlyOriginalFollowsTheClosedForm) {
  for (const int agents : {50, 100, 150}) {
    const BayindirRates rates = bayindir_rates(testing::bayindir_world(agents, 0.0, false, false),
                                               CreationVariant::Original);
    const double k = rates.creation.coefficient;
    const double tolerance = euler_tolerance(k, agents);
    BayindirState state = BayindirState::all_searching(agents);
    for (std::int64_t t = 1; t <= 50000; ++t) {
      advance_expected(rates, state);
      const double closed_form = agents / (1.0 + 2.0 * k * agents * static_cast<double>(t));
      ASSERT_NEAR(state.searching / closed_form, 1.0, tolerance) << "N " << agents << " t " << t;
    }
  }
}

// A world of one agent: nobody to pair with, in every variant (the original's C y^2 had taken
// 0.26 of the agent out of the model over 1,000 tu of full-0.0025's rates).
TEST(BayindirExpected, OneAgentAloneStaysSearchingInEveryVariant) {
  for (const CreationVariant variant : {CreationVariant::Original, CreationVariant::Collision}) {
    const BayindirRates rates =
        bayindir_rates(testing::bayindir_world(1, 0.0025, true, true), variant);
    const BayindirState state = run_steps(rates, 10000);
    EXPECT_EQ(state.searching, 1.0);
    EXPECT_EQ(state.noa(), 0.0);
    EXPECT_EQ(state.totals.creations, 0.0);
  }
}

TEST(BayindirExpected, CreationOnlyCollisionFollowsTheOrderedPairSolution) {
  // dy/dt = -2k y (y - 1) gives (y - 1)/y = (1 - 1/N) e^{-2kt}; it differs from the
  // closed form N / (1 + 2kNt) by at most about one agent (y -> 1 instead of 0).
  const int agents = 150;
  const BayindirRates rates = bayindir_rates(testing::bayindir_world(agents, 0.0, false, false),
                                             CreationVariant::Collision);
  const double k = rates.creation.coefficient;
  const double tolerance = euler_tolerance(k, agents);
  BayindirState state = BayindirState::all_searching(agents);
  for (std::int64_t t = 1; t <= 50000; ++t) {
    advance_expected(rates, state);
    const double time = static_cast<double>(t);
    const double exact = 1.0 / (1.0 - (1.0 - 1.0 / agents) * std::exp(-2.0 * k * time));
    ASSERT_NEAR(state.searching / exact, 1.0, tolerance) << "t " << t;
    const double closed_form = agents / (1.0 + 2.0 * k * agents * time);
    ASSERT_LE(std::abs(state.searching - closed_form), 1.0 + tolerance * closed_form) << t;
  }
  EXPECT_NEAR(state.noa(), (agents - state.searching) / 2.0, 1e-9);
}

// Root of k y(y-1) = p (N - y) (ordered pairs) or k y^2 = p (N - y) (squared).
double steady_searchers(const PairRate& creation, double p, int agents) {
  const double k = creation.coefficient;
  const double linear = creation.pairs == PairCount::Ordered ? p - k : p;
  return (-linear + std::sqrt(linear * linear + 4.0 * k * p * agents)) / (2.0 * k);
}

TEST(BayindirExpected, CreationDissipationSettlesAtTheRootOfTheBalance) {
  const int agents = 150;
  for (const double p : {1e-4, 5e-4, 1e-3, 5e-3}) {
    for (const CreationVariant variant : {CreationVariant::Original, CreationVariant::Collision}) {
      const BayindirRates rates =
          bayindir_rates(testing::bayindir_world(agents, p, false, true), variant);
      // Slowest relaxation rate 2p + 2k(2y - 1) >= 2e-4 per step: 2e5 steps is e^-40.
      const BayindirState state = run_steps(rates, 200000);
      const double root = steady_searchers(rates.creation, p, agents);
      EXPECT_NEAR(state.searching, root, 1e-9 * agents) << "p " << p;
      EXPECT_NEAR(state.noa(), (agents - root) / 2.0, 1e-9 * agents) << "p " << p;
    }
  }
}

TEST(BayindirExpected, ConservesAgentsEveryStep) {
  for (const double p : {5e-4, 2.5e-3}) {
    const BayindirRates rates =
        bayindir_rates(testing::bayindir_world(120, p, true, true), CreationVariant::Collision);
    BayindirState state = BayindirState::all_searching(120);
    for (int step = 0; step < 50000; ++step) {
      advance_expected(rates, state);
      ASSERT_NEAR(state.agents_accounted(), 120.0, 1e-9) << "step " << step;
      ASSERT_GE(state.searching, 0.0);
      for (double n : state.aggregates) ASSERT_GE(n, 0.0);
    }
    EXPECT_GT(state.largest_expected(), 2.0);  // growth happened
  }
}

TEST(BayindirExpected, OneStepMatchesHandComputedEvents) {
  // Full rules, 2 searchers, one aggregate of 2 and one of 3, by hand from the equations.
  BayindirRates rates;
  rates.agents = 7;
  rates.creation = {0.01, PairCount::Ordered};
  rates.growth = {0, 0, 0.1, 0.05, 0.04, 0.03, 0.02, 0};
  rates.loss = {0, 0, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  BayindirState state = BayindirState::all_searching(7);
  state.searching = 2;
  state.aggregates[2] = 1;
  state.aggregates[3] = 1;
  advance_expected(rates, state);
  const double creation = 0.01 * 2 * 1, grow2 = 1 * 2 * 0.1, grow3 = 1 * 2 * 0.05;
  const double dissipate = 0.2, shrink3 = 0.3;
  EXPECT_NEAR(state.searching, 2 - 2 * creation - grow2 - grow3 + 2 * dissipate + shrink3, 1e-15);
  EXPECT_NEAR(state.aggregates[2], 1 + creation - dissipate - grow2 + shrink3, 1e-15);
  EXPECT_NEAR(state.aggregates[3], 1 + grow2 - grow3 - shrink3, 1e-15);
  EXPECT_NEAR(state.aggregates[4], grow3, 1e-15);
  EXPECT_NEAR(state.agents_accounted(), 7.0, 1e-14);
  EXPECT_NEAR(state.totals.growths, grow2 + grow3, 1e-15);
  EXPECT_NEAR(state.totals.dissipations, dissipate, 1e-15);
  EXPECT_NEAR(state.totals.shrinks, shrink3, 1e-15);
}

TEST(BayindirExpected, RulesKeepAggregatesAsTheExperimentsDo) {
  const BayindirRates creation_only =
      bayindir_rates(testing::bayindir_world(150, 1e-3, false, false), CreationVariant::Collision);
  const BayindirState pairs = run_steps(creation_only, 20000);
  for (int m = 3; m <= 150; ++m) EXPECT_EQ(pairs.aggregates[m], 0.0);
  EXPECT_EQ(pairs.totals.dissipations, 0.0);
  const BayindirRates growing =
      bayindir_rates(testing::bayindir_world(80, 1e-3, true, false), CreationVariant::Collision);
  const BayindirState grown = run_steps(growing, 20000);
  EXPECT_GT(grown.totals.growths, 0.0);
  EXPECT_EQ(grown.totals.dissipations + grown.totals.shrinks, 0.0);
}

TEST(BayindirExpected, CollisionWorldCountsEncountersAtConstantRate) {
  WorldSpec world = testing::bayindir_world(100, 0.0, true, true, 540.0);
  world.controller.type = "collision";
  world.run.duration = 100.0;
  const BayindirRates rates = bayindir_rates(world, CreationVariant::Collision);
  const auto rows = bayindir_expected_series(rates, {0, 500, 1000});
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_FALSE(rows[2].noa.has_value());
  // Z = 0.1729 encounters per tu (see kinetic_rate_test) for 100 tu.
  EXPECT_NEAR(*rows[2].encounters, 17.290907397638014, 1e-9);
  EXPECT_NEAR(*rows[1].encounters, 17.290907397638014 / 2, 1e-9);
}

TEST(BayindirExpected, LargestIsWhereAtLeastHalfAnAggregateRemains) {
  BayindirState state = BayindirState::all_searching(20);
  EXPECT_EQ(state.largest_expected(), 0.0);
  state.aggregates[2] = 3.0;
  state.aggregates[5] = 0.3;
  state.aggregates[7] = 0.3;
  EXPECT_EQ(state.largest_expected(), 5.0);  // 0.3 of size >= 7, 0.6 of size >= 5
  EXPECT_EQ(state.largest_present(), 7.0);
}

}  // namespace
}  // namespace swarmagg
