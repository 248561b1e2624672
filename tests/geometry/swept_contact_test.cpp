#include "geometry/swept_contact.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(FirstContactTime, HeadOnPairMeetsWhenTheGapCloses) {
  // 10 apart, closing at 2 u/tu, reach 4: contact after 3 tu.
  const auto t = first_contact_time({10.0, 0.0}, {-2.0, 0.0}, 4.0, 0.0, 5.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 3.0, 1e-12);
}

TEST(FirstContactTime, StartTimeOffsetsTheResult) {
  const auto t = first_contact_time({10.0, 0.0}, {-2.0, 0.0}, 4.0, 1.0, 5.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 4.0, 1e-12);
}

TEST(FirstContactTime, GlancingPassWithinReachIsFound) {
  // Passes at closest distance 3 (< 4): contact where x^2 + 9 = 16, x = sqrt(7).
  const auto t = first_contact_time({10.0, 3.0}, {-1.0, 0.0}, 4.0, 0.0, 20.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 10.0 - std::sqrt(7.0), 1e-12);
}

TEST(FirstContactTime, PassingFartherThanReachIsNoContact) {
  EXPECT_FALSE(first_contact_time({10.0, 4.5}, {-1.0, 0.0}, 4.0, 0.0, 100.0));
}

TEST(FirstContactTime, AlreadyWithinReachIsNotAFirstContact) {
  EXPECT_FALSE(first_contact_time({3.0, 0.0}, {-1.0, 0.0}, 4.0, 0.0, 1.0));
}

TEST(FirstContactTime, MovingApartOrStillNeverMeets) {
  EXPECT_FALSE(first_contact_time({10.0, 0.0}, {1.0, 0.0}, 4.0, 0.0, 100.0));
  EXPECT_FALSE(first_contact_time({10.0, 0.0}, {0.0, 0.0}, 4.0, 0.0, 100.0));
}

TEST(FirstContactTime, ContactAfterTheIntervalIsNotReported) {
  EXPECT_FALSE(first_contact_time({10.0, 0.0}, {-2.0, 0.0}, 4.0, 0.0, 2.9));
}

TEST(FirstContactTime, FastAgentsThatCrossInOneStepStillMeet) {
  // Relative displacement of 100 u in one step, far more than the reach: the pair passes
  // through each other within the step and the contact is at the entry point.
  const auto t = first_contact_time({50.0, 1.0}, {-1000.0, 0.0}, 4.0, 0.0, 0.1);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, (50.0 - std::sqrt(15.0)) / 1000.0, 1e-15);
}

}  // namespace
}  // namespace swarmagg
