#include "models/bayindir_rates.hpp"

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

TEST(BayindirRates, GrowthUsesTheCaptureRadius) {
  const BayindirRates rates =
      bayindir_rates(testing::bayindir_world(120, 5e-4, true, true), CreationVariant::Collision);
  // rho_2 = s + R1(2) - s/4 = 4 + 1.6737 - 1; g_2 = 2 rho_2 v dt / A.
  EXPECT_NEAR(rates.growth[2], 2.884995308407708e-05, 1e-18);
  EXPECT_GT(rates.growth[3], rates.growth[2]);
  EXPECT_EQ(rates.growth[120], 0.0);  // sizes are truncated at N
}

TEST(BayindirRates, LossIsDissipationThenCappedPeriphery) {
  const double p = 5e-4;
  const BayindirRates rates =
      bayindir_rates(testing::bayindir_world(120, p, true, true), CreationVariant::Collision);
  EXPECT_DOUBLE_EQ(rates.loss[2], 2 * p);
  EXPECT_DOUBLE_EQ(rates.loss[3], 3 * p);  // periph(3) = 3.25 capped at 3
  EXPECT_DOUBLE_EQ(rates.loss[4], 4 * p);
  EXPECT_NEAR(rates.loss[10], 8.243357113223203 * p, 1e-15);
}

TEST(BayindirRates, RulesSwitchEventsOff) {
  const BayindirRates creation_only =
      bayindir_rates(testing::bayindir_world(150, 1e-3, false, false), CreationVariant::Original);
  for (double g : creation_only.growth) EXPECT_EQ(g, 0.0);
  for (double l : creation_only.loss) EXPECT_EQ(l, 0.0);
  const BayindirRates dissipation =
      bayindir_rates(testing::bayindir_world(150, 1e-3, false, true), CreationVariant::Original);
  EXPECT_EQ(dissipation.growth[2], 0.0);
  EXPECT_EQ(dissipation.loss[2], 2e-3);
  EXPECT_TRUE(dissipation.forms_aggregates);
}

TEST(BayindirRates, CollisionWorldsOnlyCountEncounters) {
  WorldSpec world = testing::bayindir_world(100, 0.0, true, true, 540.0);
  world.controller.type = "collision";
  EXPECT_FALSE(bayindir_rates(world, CreationVariant::Collision).forms_aggregates);
}

TEST(BayindirRates, RejectsAStepTooCoarseForProbabilities) {
  WorldSpec world = testing::bayindir_world(150, 0.6, true, true);
  EXPECT_THROW(bayindir_rates(world, CreationVariant::Collision), InputError);  // 2p > 1
  world.controller.p_leave = 1e-3;
  world.engine.dt = 200.0;  // creation alone would use more than every searcher per step
  EXPECT_THROW(bayindir_rates(world, CreationVariant::Collision), InputError);
}

// The rim of a large enough aggregate leaves with a probability above 1 per step whatever the
// step: the message says so instead of asking for a smaller engine.dt, which cannot help.
TEST(BayindirRates, SaysWhenNoStepCanHoldTheLargestAggregatesLosses) {
  WorldSpec world = testing::bayindir_world(2000, 0.05, true, true);
  world.engine.dt = 1e-4;
  try {
    bayindir_rates(world, CreationVariant::Collision);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("loses a member with probability"), std::string::npos) << message;
    EXPECT_NE(message.find("engine.dt does not change"), std::string::npos) << message;
    EXPECT_EQ(message.find("reduce engine.dt"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace swarmagg
