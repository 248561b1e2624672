#include "controllers/compaction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace swarmagg {
namespace {

// Every squared norm below standing_norm2(t) must have a norm under t (the controller stands
// such agents without the square root), and the bound must sit just under t^2, or the
// shortcut would rarely apply.
TEST(StandingNorm2, EverySquareBelowItHasARootUnderTheTolerance) {
  for (const double t : {0.05, 0.1, 1.0, 3.0, 1e-3, 0.3, 7.77, 1e-150}) {
    const double bound = standing_norm2(t);
    EXPECT_LT(std::sqrt(bound), t) << t;
    EXPECT_LT(std::sqrt(std::nextafter(bound, 0.0)), t) << t;
    EXPECT_GE(bound, t * t * (1.0 - 4 * std::numeric_limits<double>::epsilon())) << t;
  }
  // sqrt(1) is exactly 1, not under it: the bound is the double below.
  EXPECT_EQ(standing_norm2(1.0), std::nextafter(1.0, 0.0));
}

TEST(StandingNorm2, WithoutAPositiveToleranceNothingIsShortCut) {
  EXPECT_EQ(standing_norm2(0.0), 0.0);
  EXPECT_EQ(standing_norm2(-1.0), 0.0);
  EXPECT_EQ(standing_norm2(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_EQ(standing_norm2(1e-200), 0.0);  // the square underflows to 0
}

}  // namespace
}  // namespace swarmagg
