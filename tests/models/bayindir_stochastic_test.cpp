#include "models/bayindir_stochastic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <span>

#include "model_test_worlds.hpp"
#include "models/bayindir_expected.hpp"
#include "models/sample_statistics.hpp"

namespace swarmagg {
namespace {

TEST(BayindirStochastic, ConservesWholeAgentsEveryStep) {
  const BayindirRates rates =
      bayindir_rates(testing::bayindir_world(120, 2.5e-3, true, true), CreationVariant::Collision);
  BayindirState state = BayindirState::all_searching(120);
  const CounterRng rng = CounterRng::for_replicate(11, 0);
  for (std::uint64_t step = 0; step < 30000; ++step) {
    UniformStream uniforms(rng, step, 1);
    advance_stochastic(rates, state, uniforms);
    ASSERT_EQ(state.agents_accounted(), 120.0) << "step " << step;
    ASSERT_GE(state.searching, 0.0);
    for (const double n : state.aggregates) {
      ASSERT_GE(n, 0.0);
      ASSERT_EQ(n, std::floor(n));
    }
  }
  EXPECT_GT(state.totals.shrinks, 0.0);
  EXPECT_GT(state.totals.dissipations, 0.0);
}

// The walk over sizes stops above the largest aggregate; the bound it keeps must stay an
// upper bound, and the largest aggregate found through it the one a full search finds.
TEST(BayindirStochastic, KeptSizeBoundNeverHidesAnAggregate) {
  const BayindirRates rates =
      bayindir_rates(testing::bayindir_world(120, 5e-4, true, true), CreationVariant::Collision);
  BayindirState state = BayindirState::all_searching(120);
  const CounterRng rng = CounterRng::for_replicate(5, 0);
  double largest_seen = 0.0;
  for (std::uint64_t step = 0; step < 30000; ++step) {
    UniformStream uniforms(rng, step, 1);
    advance_stochastic(rates, state, uniforms);
    double searched = 0.0;
    for (int m = 2; m <= state.agents(); ++m) {
      if (state.aggregates[static_cast<std::size_t>(m)] > 0.0) searched = m;
    }
    ASSERT_TRUE(state.size_bound.has_value());
    ASSERT_GE(*state.size_bound, searched) << "step " << step;
    ASSERT_EQ(state.largest_present(), searched) << "step " << step;
    largest_seen = std::max(largest_seen, searched);
  }
  EXPECT_GT(largest_seen, 5.0);  // aggregates grew, so the bound moved
}

// Statistics over the replicates walk them side by side; the timeseries lists them one after
// another. Both must see the same states, from a start or from all searching.
TEST(BayindirStochastic, SideBySideReplicatesAreTheOnesRunOneByOne) {
  const BayindirRates rates =
      bayindir_rates(testing::bayindir_world(60, 2.5e-3, true, true), CreationVariant::Collision);
  const std::vector<std::int64_t> grid{0, 10, 500, 3000};
  const std::vector<double> start{0.0, 0.0, 3.0, 1.0};
  for (const auto& first_decision : {std::vector<double>{}, start}) {
    const auto rows = bayindir_stochastic_series(rates, grid, 9, 4, 2, first_decision);
    std::size_t point = 0;
    walk_stochastic_side_by_side(
        rates, grid, 9, 4, 2, first_decision,
        [&](std::span<const BayindirState> states, std::int64_t step) {
          ASSERT_EQ(states.size(), 4u);
          for (std::size_t k = 0; k < states.size(); ++k) {
            const ModelRow& row = rows[k * grid.size() + point];
            ASSERT_EQ(row.step, step);
            EXPECT_EQ(states[k].noa(), *row.noa) << "replicate " << k << ", step " << step;
            EXPECT_EQ(states[k].searching, *row.searching) << "replicate " << k;
            EXPECT_EQ(states[k].totals.growths, *row.growths) << "replicate " << k;
          }
          ++point;
        });
    EXPECT_EQ(point, grid.size());
  }
}

TEST(BayindirStochastic, ReproducibleForASeedAndDifferentAcrossSeeds) {
  const BayindirRates rates =
      bayindir_rates(testing::bayindir_world(120, 5e-4, true, true), CreationVariant::Original);
  const std::vector<std::int64_t> grid{0, 1000, 5000};
  auto noa_values = [&](std::uint64_t seed) {
    std::vector<double> values;
    for (const auto& row : bayindir_stochastic_series(rates, grid, seed, 3, 0)) {
      values.push_back(*row.noa);
    }
    return values;
  };
  EXPECT_EQ(noa_values(5), noa_values(5));
  EXPECT_NE(noa_values(5), noa_values(6));
}

// Mean of the stochastic replicates against the expected-value model at several steps.
// Given the state, a stochastic step's expected events equal the difference equations
// exactly, so the means differ only through the rates' non-linearity (E[y(y-1)] exceeds
// E[y](E[y]-1) by Var y), an O(1) bias in agents; with many agents and few replicates it is
// well inside the 4-standard-error tolerance, which a wrong event rate would exceed.
void expect_means_agree(const WorldSpec& world, CreationVariant variant, int replicates) {
  const BayindirRates rates = bayindir_rates(world, variant);
  const std::vector<std::int64_t> grid{100, 500, 2000, 8000};
  const auto expected = bayindir_expected_series(rates, grid);
  const auto stochastic = bayindir_stochastic_series(rates, grid, 2024, replicates, 0);
  for (std::size_t g = 0; g < grid.size(); ++g) {
    for (auto field : {&ModelRow::noa, &ModelRow::searching}) {
      std::vector<double> values;
      for (const auto& row : stochastic) {
        if (row.step == grid[g]) values.push_back(*(row.*field));
      }
      ASSERT_EQ(values.size(), static_cast<std::size_t>(replicates));
      const double standard_error = sample_sd(values) / std::sqrt(replicates);
      ASSERT_GT(standard_error, 0.0);
      EXPECT_NEAR(sample_mean(values), *(expected[g].*field), 4 * standard_error)
          << "step " << grid[g];
    }
  }
}

TEST(BayindirStochastic, MeanConvergesToTheExpectedValueModel) {
  // 600 agents at the paper's density (150 on 180x180).
  const double side = 360.0;
  expect_means_agree(testing::bayindir_world(600, 0.0, false, false, side),
                     CreationVariant::Original, 30);
  expect_means_agree(testing::bayindir_world(600, 1e-3, false, true, side),
                     CreationVariant::Collision, 30);
  expect_means_agree(testing::bayindir_world(600, 2.5e-3, true, true, side),
                     CreationVariant::Collision, 30);
  expect_means_agree(testing::bayindir_world(600, 5e-4, true, true, side),  // growth matters
                     CreationVariant::Collision, 30);
}

TEST(BayindirStochastic, CollisionWorldEncountersMatchTheRate) {
  WorldSpec world = testing::bayindir_world(100, 0.0, true, true, 540.0);
  world.controller.type = "collision";
  const BayindirRates rates = bayindir_rates(world, CreationVariant::Collision);
  const auto rows = bayindir_stochastic_series(rates, {0, 10000}, 1, 20, 0);
  std::vector<double> totals;
  for (const auto& row : rows) {
    if (row.step == 10000) totals.push_back(*row.encounters);
  }
  // 1000 tu at Z = 0.1729 per tu; counts are nearly Poisson, sd ~ sqrt(173) / sqrt(20).
  EXPECT_NEAR(sample_mean(totals), 172.90907397638014, 4 * std::sqrt(172.9 / 20));
}

}  // namespace
}  // namespace swarmagg
