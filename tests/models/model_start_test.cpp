// Both models start from the state after the first decision (model.initial_state).
#include <gtest/gtest.h>

#include "model_test_worlds.hpp"
#include "models/bayindir_expected.hpp"
#include "models/bayindir_stochastic.hpp"
#include "models/initial_state.hpp"
#include "models/output_grid.hpp"
#include "models/predictions.hpp"
#include "models/soysal_model.hpp"

namespace swarmagg {
namespace {

TEST(ModelStart, BayindirHoldsTheFirstDecisionsAggregatesAtStepOne) {
  const WorldSpec world = testing::bayindir_world(150, 0.0, true, false);
  const BayindirRates rates = bayindir_rates(world, CreationVariant::Collision);
  const std::vector<double> start = start_aggregates(world, nullptr, nullptr);
  const std::vector<ModelRow> rows = bayindir_expected_series(rates, {0, 1, 2}, start);
  EXPECT_EQ(*rows[0].noa, 0.0);
  EXPECT_NEAR(*rows[1].noa, start[2] + start[3], 1e-12);
  EXPECT_NEAR(*rows[1].searching, 150.0 - 2.0 * start[2] - 3.0 * start[3], 1e-12);
  EXPECT_NEAR(*rows[1].growths, start[3], 1e-12);  // a triple: a pair and a join
  // From step 1 on the rates act as before.
  EXPECT_GT(*rows[2].creations, *rows[1].creations);
  // Without a start the first step is an ordinary step of the rates.
  const std::vector<ModelRow> plain = bayindir_expected_series(rates, {0, 1});
  EXPECT_NEAR(*plain[1].creations, rates.creation.at(150), 1e-12);
}

TEST(ModelStart, StochasticFirstDecisionsAverageToTheExpectation) {
  const std::vector<double> start = {0.0, 0.0, 3.0, 0.5};
  double pairs = 0.0, triples = 0.0;
  constexpr int kDraws = 4000;
  for (int i = 0; i < kDraws; ++i) {
    UniformStream uniforms(CounterRng::for_replicate(5, static_cast<std::uint64_t>(i)), 0, 0);
    const BayindirState state = draw_first_decision(40, start, uniforms);
    EXPECT_DOUBLE_EQ(state.agents_accounted(), 40.0);
    pairs += state.aggregates[2];
    triples += state.aggregates[3];
  }
  // Binomial counts: sd below sqrt(mean), so the means are within 4 sd / sqrt(draws).
  EXPECT_NEAR(pairs / kDraws, 3.0, 4.0 * std::sqrt(3.0 / kDraws));
  EXPECT_NEAR(triples / kDraws, 0.5, 4.0 * std::sqrt(0.5 / kDraws));
}

TEST(ModelStart, SoysalStartsFromPoissonCountsOfThePlacementPairs) {
  const WorldSpec world = testing::soysal_world(5, 150.0);
  const std::vector<double> start = start_aggregates(world, nullptr, nullptr);
  ASSERT_GT(start[2], 0.0);
  const VariantPrediction prediction = soysal_prediction(
      world, soysal_rates(world, LeavingVariant::Peripheral), "peripheral", start);
  double at_zero = -1.0, pair_at_one = -1.0;
  for (const TidyValue& v : prediction.extra) {
    if (v.quantity == "partition:1+1+1+1+1" && v.step == 0) at_zero = v.value;
  }
  EXPECT_DOUBLE_EQ(at_zero, 1.0);
  // The first reported step after 0 lies on the record grid; its pair probability is at
  // least the placement's P(one pair) minus what the chain could move in that time.
  const WorldSpec all_searching = [&] {
    WorldSpec w = world;
    w.model.initial_state = InitialState::AllSearching;
    return w;
  }();
  const VariantPrediction from_free = soysal_prediction(all_searching, LeavingVariant::Peripheral);
  for (std::size_t i = 0; i < prediction.extra.size(); ++i) {
    const TidyValue& v = prediction.extra[i];
    if (v.quantity == "partition:2+1+1+1" && v.step && *v.step > 0 && pair_at_one < 0.0) {
      pair_at_one = v.value;
      EXPECT_GT(v.value, from_free.extra[i].value);  // more pairs than from all free
    }
  }
  EXPECT_GT(pair_at_one, 0.0);
}

}  // namespace
}  // namespace swarmagg
