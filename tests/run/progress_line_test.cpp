// The progress line in a log (stderr is not a terminal here): its last line counts every unit.
#include "run/progress_line.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace swarmagg {
namespace {

// A unit's work is counted before the unit is: a log line due in between says 100 % with
// units still open, and the log still ends with the line that counts them all.
TEST(ProgressLine, ALogEndsWithEveryUnitCountedThoughAllWorkWasLoggedBefore) {
  ::testing::internal::CaptureStderr();
  ProgressLine progress("tiny", "runs", 2, 100.0);
  progress.add_work(50.0);
  progress.finished_unit();
  progress.add_work(50.0);
  progress.report();  // all the work done, the second run still writing its outputs
  progress.finished_unit();
  progress.finish();
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(std::regex_search(log, std::regex(R"(^tiny: 1/2 runs  100\.0% done)"))) << log;
  EXPECT_TRUE(std::regex_search(log, std::regex(R"(\ntiny: 2/2 runs  100\.0% done[^\n]*\n$)")))
      << log;
}

TEST(ProgressLine, ALogLineThatCountedEverythingIsNotRepeatedAtTheEnd) {
  ::testing::internal::CaptureStderr();
  ProgressLine progress("tiny", "runs", 1, 10.0);
  progress.add_work(10.0);
  progress.finished_unit();
  progress.report();
  progress.finish();
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(std::regex_match(log, std::regex(R"(tiny: 1/1 runs  100\.0% done[^\n]*\n)"))) << log;
}

}  // namespace
}  // namespace swarmagg
