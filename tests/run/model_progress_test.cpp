// The progress line of a model computation, without waiting for its quiet second: the quiet
// period is the constructor's to set.
#include "run/model_progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <regex>
#include <string>

#include "run/interrupt.hpp"

namespace swarmagg {
namespace {

using std::chrono::milliseconds;

// Two variants of 50 steps each, reported as the walks report them.
std::string stderr_of_two_variants(bool shown, milliseconds quiet_for) {
  ::testing::internal::CaptureStderr();
  ModelProgress progress("demo", 2, 100.0, shown, quiet_for);
  for (int variant = 0; variant < 2; ++variant) {
    for (int batch = 0; batch < 5; ++batch) progress.add_work(10);
    progress.finished_variant();
  }
  progress.finish();
  return ::testing::internal::GetCapturedStderr();
}

// In a log (stderr is not a terminal here): one line when it first reports, and the last
// line saying every variant is done.
TEST(ModelProgress, PastItsQuietPeriodALogSaysHowManyVariantsAreDone) {
  const std::string log = stderr_of_two_variants(true, milliseconds(0));
  EXPECT_TRUE(std::regex_search(log, std::regex(R"(^demo: 0/2 variants   10\.0% done  elapsed )")))
      << log;
  EXPECT_TRUE(std::regex_search(
      log, std::regex(R"(\ndemo: 2/2 variants  100\.0% done  elapsed \d+s  eta 0s\n$)")))
      << log;
}

TEST(ModelProgress, WithinItsQuietPeriodOrNotShownItPrintsNothing) {
  EXPECT_EQ(stderr_of_two_variants(true, milliseconds(60'000)), "");
  EXPECT_EQ(stderr_of_two_variants(false, milliseconds(0)), "");
}

TEST(ModelProgress, AReportAfterCtrlCThrowsInterruptedShownOrNot) {
  for (const bool shown : {true, false}) {
    ModelProgress progress("demo", 1, 10.0, shown, milliseconds(60'000));
    set_interrupt_signal(SIGINT);
    EXPECT_THROW(progress.add_work(1), Interrupted) << shown;
    set_interrupt_signal(0);
  }
}

}  // namespace
}  // namespace swarmagg
