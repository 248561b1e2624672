#include "models/predictions.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

std::vector<std::string> variants_of(const std::vector<VariantPrediction>& predictions) {
  std::vector<std::string> names;
  for (const auto& p : predictions) names.push_back(p.model + "/" + p.variant);
  return names;
}

TEST(Predictions, BayindirWorldsGetBothCreationVariantsExpectedAndStochastic) {
  WorldSpec world = testing::bayindir_world(120, 5e-4, true, true);
  world.run.duration = 100.0;
  world.model.stochastic_replicates = 3;
  const auto predictions = predict(world);
  // Its aggregates lose agents: the returns variant too.
  const std::vector<std::string> expected{"bayindir/original",
                                          "bayindir/collision",
                                          "bayindir/returns",
                                          "bayindir/original-stochastic",
                                          "bayindir/collision-stochastic",
                                          "bayindir/returns-stochastic"};
  EXPECT_EQ(variants_of(predictions), expected);
  EXPECT_EQ(predictions[0].series.size(), 101u);  // steps 0, 10, ..., 1000
  EXPECT_EQ(predictions[4].series.size(), 3 * 101u);
  EXPECT_TRUE(predictions[4].stochastic);
  // model.creation defaults to collision: that expected and stochastic variant are chosen.
  EXPECT_FALSE(predictions[0].chosen);
  EXPECT_TRUE(predictions[1].chosen);
  EXPECT_TRUE(predictions[4].chosen);
  world.model.stochastic_replicates = 0;
  EXPECT_EQ(predict(world).size(), 3u);
}

TEST(Predictions, SoysalWorldsGetBothLeavingVariants) {
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.run.duration = 1e5;
  const auto predictions = predict(world);
  const std::vector<std::string> expected{"soysal/original", "soysal/peripheral", "soysal/returns"};
  EXPECT_EQ(variants_of(predictions), expected);
  EXPECT_TRUE(predictions[1].chosen);  // model.leaving defaults to peripheral
  for (const VariantPrediction& p : predictions) {
    const bool has_floor = std::any_of(p.extra.begin(), p.extra.end(), [](const TidyValue& v) {
      return v.quantity == "noise_floor:tv_partition" && v.value > 0.0 && v.value < 1.0;
    });
    EXPECT_TRUE(has_floor) << p.variant;
  }
  const std::string summary = prediction_summary(predictions[1]);
  EXPECT_NE(summary.find("most likely partition"), std::string::npos) << summary;
}

// The size distribution at the last step accounts for every agent: the aggregated ones
// (sum of m n_m) plus the free ones the last row predicts.
double agents_in_size_distribution(const VariantPrediction& prediction) {
  double aggregated = 0.0;
  for (const TidyValue& value : prediction.extra) {
    if (!value.quantity.starts_with(kAggregatesOfSize)) continue;
    EXPECT_EQ(value.step, prediction.series.back().step) << value.quantity;
    aggregated +=
        std::stod(value.quantity.substr(std::string(kAggregatesOfSize).size())) * value.value;
  }
  return aggregated + *prediction.series.back().searching;
}

TEST(Predictions, ExpectedVariantsGiveTheirSizeDistributionAtTheLastStep) {
  WorldSpec bayindir = testing::bayindir_world(120, 5e-4, true, true);
  bayindir.run.duration = 200.0;
  bayindir.model.stochastic_replicates = 0;
  for (const VariantPrediction& p : predict(bayindir))
    EXPECT_NEAR(agents_in_size_distribution(p), 120.0, 1e-2) << p.variant;
  WorldSpec soysal = testing::soysal_world(5, 150.0);
  soysal.run.duration = 1e5;
  for (const VariantPrediction& p : predict(soysal))
    EXPECT_NEAR(agents_in_size_distribution(p), 5.0, 1e-6) << p.variant;
}

TEST(Predictions, CollisionWorldsPredictEncounters) {
  WorldSpec world = testing::bayindir_world(100, 0.0, true, true, 540.0);
  world.controller.type = "collision";
  world.run.duration = 100.0;
  world.model.stochastic_replicates = 2;
  const auto predictions = predict(world);
  ASSERT_EQ(predictions.size(), 4u);
  EXPECT_FALSE(predictions[1].series.back().noa.has_value());
  EXPECT_NEAR(*predictions[1].series.back().encounters, 17.290907397638014, 1e-9);
  EXPECT_NE(prediction_summary(predictions[1]).find("encounters"), std::string::npos);
  EXPECT_FALSE(model_caveats(world).empty());
}

TEST(Predictions, CaveatsNameDeparturesFromTheModelAssumptions) {
  WorldSpec world = testing::bayindir_world(120, 5e-4, true, false);
  world.model.initial_state = InitialState::Placement;
  EXPECT_TRUE(model_caveats(world).empty());
  world.controller.isolated_wait = IsolatedWait::Stay;
  world.arena.topology = Topology::Walls;
  EXPECT_EQ(model_caveats(world).size(), 2u);
  // A world that leaves also gets the caveat every leaving world shares, which runs omit.
  world.controller.p_leave = 0.01;
  world.controller.leave = true;
  const std::vector<std::string> caveats = model_caveats(world);
  ASSERT_EQ(caveats.size(), 3u);
  EXPECT_NE(caveats[0].find("no LEAVE timeout"), std::string::npos);
  EXPECT_EQ(world_caveats(world), (std::vector<std::string>{caveats[1], caveats[2]}));
}

TEST(Predictions, TheSecondOrderStartIsFlaggedWhereAgentsStartCrowded) {
  // 120 agents on 180 x 180: each starts with 119 pi (4^2 - 2^2) / 180^2 = 0.14 others within s.
  WorldSpec world = testing::bayindir_world(120, 5e-4, true, false);
  const std::vector<std::string> caveats = model_caveats(world);
  ASSERT_EQ(caveats.size(), 1u);
  EXPECT_NE(caveats[0].find("placement_second_order"), std::string::npos);
  EXPECT_NE(caveats[0].find(" 0.14 others"), std::string::npos);
  world.robots.count = 60;  // 0.068 others
  EXPECT_TRUE(model_caveats(world).empty());
}

}  // namespace
}  // namespace swarmagg
