#include "models/soysal_rates.hpp"

#include <gtest/gtest.h>

#include "config/leave_law.hpp"
#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

// 5 agents on 150x150 (A = 22500), s_a = 12, r = 1, v = 1, dt = 0.1, p0 = 2e-5.
TEST(SoysalRates, EncounterProbabilitiesAreSweptAreas) {
  const SoysalRates rates = soysal_rates(testing::soysal_world(5, 150.0), LeavingVariant::Original);
  EXPECT_NEAR(rates.pair_up, 0.00013581221810508404, 1e-18);  // 2 * 12 * (4/pi) * 0.1 / A
  EXPECT_NEAR(rates.join[3], 0.00011585147180946317, 1e-18);  // 2 (1.2 * 3^0.48 + 12 - 1) 0.1 / A
}

TEST(SoysalRates, LeaveLaws) {
  EXPECT_DOUBLE_EQ(leave_probability(LeaveLaw::Constant, 2e-5, 4), 2e-5);
  EXPECT_DOUBLE_EQ(leave_probability(LeaveLaw::Inverse, 2e-5, 4), 5e-6);
  EXPECT_DOUBLE_EQ(leave_probability(LeaveLaw::InverseSquare, 2e-5, 4), 1.25e-6);
}

TEST(SoysalRates, OriginalLeavingCountsEveryMember) {
  WorldSpec world = testing::soysal_world(10, 212.0, 2e-5, LeaveLaw::Inverse);
  const SoysalRates rates = soysal_rates(world, LeavingVariant::Original);
  EXPECT_DOUBLE_EQ(rates.leave[2], 2 * 2e-5 / 2);
  EXPECT_DOUBLE_EQ(rates.leave[7], 7 * 2e-5 / 7);
}

TEST(SoysalRates, PeripheralLeavingWithAndWithoutCap) {
  WorldSpec world = testing::soysal_world(10, 212.0);
  world.model.periphery_cap = false;
  const SoysalRates uncapped = soysal_rates(world, LeavingVariant::Peripheral);
  EXPECT_NEAR(uncapped.leave[3], 3.2461780906421134 * 2e-5, 1e-18);
  EXPECT_NEAR(uncapped.leave[2], 2.116467093426999 * 2e-5, 1e-18);
  EXPECT_NEAR(uncapped.leave[10], 8.243357113223203 * 2e-5, 1e-18);
  world.model.periphery_cap = true;
  const SoysalRates capped = soysal_rates(world, LeavingVariant::Peripheral);
  EXPECT_DOUBLE_EQ(capped.leave[3], 3 * 2e-5);
  EXPECT_NEAR(capped.leave[10], 8.243357113223203 * 2e-5, 1e-18);
}

TEST(SoysalRates, RulesSwitchEventsOff) {
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.controller.join = false;
  world.controller.leave = false;
  const SoysalRates rates = soysal_rates(world, LeavingVariant::Original);
  EXPECT_GT(rates.pair_up, 0.0);
  for (int i = 2; i <= 5; ++i) {
    EXPECT_EQ(rates.join[i], 0.0);
    EXPECT_EQ(rates.leave[i], 0.0);
  }
}

}  // namespace
}  // namespace swarmagg
