#include "view/run_control.hpp"

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "view/view_command.hpp"

namespace swarmagg {
namespace {

TEST(RunControl, StartsPausedAndTakesOnlyRequestedSteps) {
  RunControl control(100, 0.1);
  EXPECT_FALSE(control.playing());
  EXPECT_EQ(control.steps_for_frame(0, 0.016), 0);
  control.request_steps(1);
  control.request_steps(2);
  EXPECT_EQ(control.steps_for_frame(0, 0.016), 3);
  EXPECT_EQ(control.steps_for_frame(3, 0.016), 0);  // requests are used up
}

TEST(RunControl, PlaysAFixedNumberOfStepsPerFrameClamped) {
  RunControl control(1000, 0.1);
  control.play();
  EXPECT_EQ(control.steps_for_frame(0, 0.016), 1);
  control.set_steps_per_frame(50);
  EXPECT_EQ(control.steps_for_frame(1, 0.016), 50);
  control.set_steps_per_frame(0);
  EXPECT_EQ(control.steps_per_frame(), 1);
  control.set_steps_per_frame(kMaxStepsPerFrame * 10);
  EXPECT_EQ(control.steps_per_frame(), kMaxStepsPerFrame);
  control.toggle();
  EXPECT_FALSE(control.playing());
  EXPECT_EQ(control.steps_for_frame(51, 0.016), 0);
}

TEST(RunControl, RealTimeCarriesFractionsOfAStep) {
  RunControl control(1000, 0.1);
  control.set_real_time(1.0);  // 1 tu per second: 10 steps per second
  control.play();
  std::int64_t total = 0;
  for (int frame = 0; frame < 60; ++frame) total += control.steps_for_frame(total, 1.0 / 60.0);
  EXPECT_GE(total, 9);
  EXPECT_LE(total, 10);
  control.set_real_time(100.0);
  EXPECT_EQ(control.steps_for_frame(total, 0.5), 500);
  EXPECT_THROW(control.set_real_time(0.0), InputError);
}

TEST(RunControl, PlayingStopsAtTheDurationOnceButExplicitStepsGoOn) {
  RunControl control(10, 0.1);
  control.set_steps_per_frame(8);
  control.play();
  EXPECT_EQ(control.steps_for_frame(0, 0.016), 8);
  EXPECT_FALSE(control.took(8));
  EXPECT_EQ(control.steps_for_frame(8, 0.016), 2);  // not past the duration
  EXPECT_TRUE(control.took(10));
  EXPECT_FALSE(control.playing());
  control.play();
  EXPECT_EQ(control.steps_for_frame(10, 0.016), 0);
  EXPECT_FALSE(control.took(10));  // reported once
  control.request_steps(3);
  EXPECT_EQ(control.steps_for_frame(10, 0.016), 3);
  control.restart();
  EXPECT_FALSE(control.playing());
  control.play();
  EXPECT_EQ(control.steps_for_frame(0, 0.016), 8);
}

TEST(RunControl, FastestAsksForTheMostAFrameMayTake) {
  RunControl control(1'000'000, 0.1);
  control.set_fastest();
  control.play();
  EXPECT_EQ(control.steps_for_frame(0, 0.016), kMaxStepsPerFrame);
  EXPECT_EQ(control.steps_for_frame(999'990, 0.016), 10);
}

}  // namespace
}  // namespace swarmagg
