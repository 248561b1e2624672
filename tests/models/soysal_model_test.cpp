#include "models/soysal_model.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "core/errors.hpp"
#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

// Sum of the `prefix` probabilities at each step (no step: stationary, key -1).
std::map<std::int64_t, double> probability_mass(const VariantPrediction& prediction,
                                                const std::string& prefix) {
  std::map<std::int64_t, double> mass;
  for (const TidyValue& value : prediction.extra) {
    if (value.quantity.starts_with(prefix)) mass[value.step.value_or(-1)] += value.value;
  }
  return mass;
}

// The chain of a large swarm takes seconds (5 s for the stationary law of N = 30): the
// caller's check for Ctrl-C is called during it, and what it throws ends the prediction.
TEST(SoysalModel, CallsItsCheckWhileTheChainIsComputedAndStopsWhenItThrows) {
  WorldSpec world = testing::soysal_world(20, 300.0);
  world.run.duration = 100000.0;
  const SoysalRates rates = soysal_rates(world, LeavingVariant::Peripheral);
  int checks = 0;
  const WalkProgress count = [&](std::int64_t work) {
    EXPECT_EQ(work, 0);
    ++checks;
  };
  soysal_prediction(world, rates, "peripheral", {}, nullptr, count);
  EXPECT_GE(checks, 10);  // 627 partitions: every 64 rows of the elimination, and the products
  struct Stop {};
  const WalkProgress stop = [](std::int64_t) { throw Stop{}; };
  EXPECT_THROW(soysal_prediction(world, rates, "peripheral", {}, nullptr, stop), Stop);
}

TEST(SoysalModel, StartsFreeAndReportsNormalisedDistributions) {
  WorldSpec world = testing::soysal_world(10, 212.0);
  world.run.duration = 500000.0;  // 5e6 steps
  const VariantPrediction prediction = soysal_prediction(world, LeavingVariant::Peripheral);
  EXPECT_EQ(prediction.model, "soysal");
  EXPECT_EQ(prediction.variant, "peripheral");
  ASSERT_GT(prediction.series.size(), 50u);
  EXPECT_EQ(prediction.series.front().step, 0);
  EXPECT_EQ(*prediction.series.front().noa, 0.0);
  EXPECT_EQ(*prediction.series.front().searching, 10.0);
  EXPECT_EQ(*prediction.series.front().largest, 0.0);
  EXPECT_EQ(prediction.series.back().step, 5000000);
  EXPECT_GT(*prediction.series.back().noa, 0.5);
  const auto partitions = probability_mass(prediction, "partition:");
  EXPECT_EQ(partitions.size(), prediction.series.size());
  for (const auto& [step, mass] : partitions) EXPECT_NEAR(mass, 1.0, 1e-12) << step;
  const auto stationary = probability_mass(prediction, "stationary:");
  ASSERT_EQ(stationary.size(), 1u);
  EXPECT_NEAR(stationary.at(-1), 1.0, 1e-12);
}

// The run average the simulation's time fractions are compared with is the model's own, not
// a trapezoid over the report steps: those are rounded to run.record_every, and a coarse
// record grid drew the early transient as a straight line (with record_every 10^5 steps, a
// TV error 0.05 off). The same world recorded more or less often averages alike.
TEST(SoysalModel, TheRunAverageDoesNotDependOnHowOftenTheRunRecords) {
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.run.duration = 100000.0;  // 10^6 steps
  std::map<int, std::map<std::string, double>> averages;
  for (const int every : {10, 1000, 100000}) {
    world.run.record_every = every;
    for (const TidyValue& value : soysal_prediction(world, LeavingVariant::Original).extra) {
      if (value.quantity.starts_with(kRunAverageQuantity)) {
        EXPECT_FALSE(value.step.has_value());
        averages[every][value.quantity] = value.value;
      }
    }
  }
  ASSERT_EQ(averages[10].size(), 7u);  // the partitions of 5
  double mass = 0.0;
  for (const auto& [quantity, value] : averages[10]) mass += value;
  EXPECT_NEAR(mass, 1.0, 1e-9);
  EXPECT_EQ(averages[1000], averages[10]);
  EXPECT_EQ(averages[100000], averages[10]);
}

TEST(SoysalModel, CappedPeripheralEqualsOriginalUpToFiveAgents) {
  // docs/models.md: with the cap, periph(i) = i for i <= 5, so the variants coincide.
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.run.duration = 1e5;
  world.model.periphery_cap = true;
  const auto original = soysal_prediction(world, LeavingVariant::Original);
  const auto capped = soysal_prediction(world, LeavingVariant::Peripheral);
  ASSERT_EQ(original.extra.size(), capped.extra.size());
  for (std::size_t i = 0; i < original.extra.size(); ++i) {
    // The noise floors are the same chain sampled on each variant's own stream.
    if (original.extra[i].quantity.starts_with("noise_floor:")) continue;
    EXPECT_NEAR(original.extra[i].value, capped.extra[i].value, 1e-14);
  }
  world.model.periphery_cap = false;  // the paper's form: leaving is faster, fewer aggregates
  const auto uncapped = soysal_prediction(world, LeavingVariant::Peripheral);
  EXPECT_LT(*uncapped.series.back().largest, *original.series.back().largest);
}

TEST(SoysalModel, NoStationaryDistributionWhenNobodyLeaves) {
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.controller.leave = false;
  world.run.duration = 1e4;
  const auto prediction = soysal_prediction(world, LeavingVariant::Original);
  EXPECT_TRUE(probability_mass(prediction, "stationary:").empty());
  EXPECT_FALSE(prediction.series.empty());
}

TEST(SoysalModel, RefusesStateSpacesTooLargeForTheDenseStationarySolve) {
  EXPECT_THROW(soysal_prediction(testing::soysal_world(31, 300.0), LeavingVariant::Original),
               InputError);
}

}  // namespace
}  // namespace swarmagg
