#include "models/return_probability.hpp"

#include <gtest/gtest.h>

#include "models/model_test_worlds.hpp"
#include "models/returns_rates.hpp"

namespace swarmagg {
namespace {

using testing::bayindir_world;
using testing::soysal_world;

// A searcher 10 from the centre of a disc of radius 5: headings within asin(1/2) = pi/6 of
// the centre reach it, a sixth of all; a reach of 6 (short of the tangent point, sqrt(75))
// only ends on the edge within acos((100 + 36 - 25) / 120) = acos(0.925) = 0.38976 rad.
TEST(ReturnProbability, HeadingCaptureFollowsTheDiscGeometry) {
  EXPECT_NEAR(heading_capture_probability(10.0, 5.0, 100.0), 1.0 / 6.0, 1e-12);
  EXPECT_NEAR(heading_capture_probability(10.0, 5.0, 6.0), 0.38976 / 3.14159265, 1e-5);
  EXPECT_EQ(heading_capture_probability(10.0, 5.0, 5.0), 0.0);  // cannot get there
  EXPECT_EQ(heading_capture_probability(4.0, 5.0, 0.0), 1.0);   // already perceives it
}

// Soysal, N = 10, s_a = 12, v = 1, size 5: R_agg(5) = 1.2 * 5^0.48 = 2.5982, R_agg(4) = 2.3344.
// Timeout 10: the leaver ends 1.5982 + 10 = 11.598 from the centre, inside the capture radius
// 1.3344 + 12 = 13.334: it comes back. Timeout 30: 31.598 away, window 90 tu leaves a reach of
// 60 beyond the tangent (28.65): q = asin(13.334 / 31.598) / pi = 0.13870.
TEST(ReturnProbability, SoysalLeaversWithinTheApproachRadiusComeBack) {
  WorldSpec world = soysal_world(10, 212.0);
  world.controller.leave_timeout = 10.0;
  EXPECT_EQ(return_probability(world, 5), 1.0);
  world.controller.leave_timeout = 30.0;
  EXPECT_NEAR(return_probability(world, 5), 0.13870, 2e-4);
}

// Bayindir (no approach: captured within s = 4), timeout 10, size 10: R1(10) = 3.624,
// R1(9) = 3.4452; D = 12.624, rho = 6.4452, q = asin(0.51056) / pi = 0.17057.
TEST(ReturnProbability, BayindirLeaversComeBackOnlyByHeadingBack) {
  WorldSpec world = bayindir_world(120, 0.0005, true, true);
  EXPECT_NEAR(return_probability(world, 10), 0.17057, 2e-4);
}

// Over every attempt: inside members come back. Size 10 has a rim share of
// periph(10) / 10 = pi (3.624 - 1) / 10 = 0.8244: 0.8244 * 0.17057 + 0.1756 = 0.31623.
TEST(ReturnProbability, InsideMembersThatTryComeBack) {
  WorldSpec world = bayindir_world(120, 0.0005, true, true);
  EXPECT_NEAR(attempt_return_probability(world, 10), 0.31623, 3e-4);
  EXPECT_EQ(attempt_return_probability(world, 5), return_probability(world, 5));  // all rim
}

// A pair's remaining agent resumes searching: nothing waits to come back to.
TEST(ReturnProbability, APairLeavesNothingToComeBackTo) {
  WorldSpec world = soysal_world(10, 212.0);
  EXPECT_EQ(return_probability(world, 2), 0.0);
  world.controller.isolated_wait = IsolatedWait::Stay;
  EXPECT_EQ(return_probability(world, 2), 1.0);
}

// The returns variant loses only the leavers that do not come back.
TEST(ReturnProbability, TheReturnsVariantKeepsTheLeaversThatComeBack) {
  WorldSpec world = soysal_world(10, 212.0);
  world.controller.leave_timeout = 30.0;
  const SoysalRates plain = soysal_rates(world, world.model.leaving);
  const SoysalRates returns = returns_soysal_rates(world);
  for (int i = 2; i <= 10; ++i) {
    EXPECT_NEAR(returns.leave[i], plain.leave[i] * (1.0 - return_probability(world, i)), 1e-15)
        << i;
    EXPECT_EQ(returns.join[i], plain.join[i]) << i;
  }
}

}  // namespace
}  // namespace swarmagg
