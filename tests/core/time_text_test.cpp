#include "core/time_text.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(TimeText, DropsTheRoundingNoiseOfStepTimesDt) {
  EXPECT_EQ(time_text(3 * 0.1), "0.3");
  EXPECT_EQ(time_text(7 * 0.1), "0.7");
  EXPECT_EQ(time_text(0.0), "0");
}

// Long runs: neighbouring steps keep distinct times (six digits print both as 1e+06).
TEST(TimeText, TellsApartTheStepsOfALongRun) {
  EXPECT_EQ(time_text(10000000 * 0.1), "1000000");
  EXPECT_EQ(time_text(10000001 * 0.1), "1000000.1");
  EXPECT_EQ(time_text(8003 * 0.0125), "100.0375");
}

}  // namespace
}  // namespace swarmagg
