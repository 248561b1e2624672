#include "rates/rates_text.hpp"

#include <gtest/gtest.h>

#include "rates/binomial_interval.hpp"
#include "rates/poisson_interval.hpp"

namespace swarmagg {
namespace {

TEST(RatesText, AReturnFractionCountsAttemptsNotEvents) {
  const std::vector<std::string> lines =
      rate_summary_lines({{.term = "return", .size = 2, .estimate = estimate_fraction(0, 19)},
                          {.term = "return", .size = 3, .estimate = estimate_fraction(5, 20)},
                          {.term = "return", .size = 4, .estimate = estimate_fraction(1, 3)}});
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].rfind("return 2: 0 [0, 0.", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(": 0 of 19 attempts returned"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find("0.25 ["), std::string::npos) << lines[1];
  EXPECT_NE(lines[1].find(": 5 of 20 attempts returned"), std::string::npos) << lines[1];
  EXPECT_EQ(lines[2], "return 4: too few attempts (3)");
}

TEST(RatesText, RatesSayHowManyEventsTheyCameFrom) {
  const std::vector<std::string> lines =
      rate_summary_lines({{.term = "creation", .estimate = estimate_rate(40, 1000.0)},
                          {.term = "growth", .size = 2, .estimate = estimate_rate(3, 1000.0)}});
  EXPECT_NE(lines[0].find(" from 40 events"), std::string::npos) << lines[0];
  EXPECT_EQ(lines[1], "growth 2: too few events (3)");
}

// A size's geometry needs observations from two replicates or more: 789 observations in one
// replicate are not "too few events".
TEST(RatesText, AnUnestimatedGeometrySaysWhatItNeeds) {
  const std::vector<std::string> lines =
      rate_summary_lines({{.term = "radius", .size = 2, .estimate = {.events = 789}}});
  EXPECT_EQ(lines[0],
            "radius 2: not estimated (789 observations; needs 10, from 2 replicates or more)");
}

}  // namespace
}  // namespace swarmagg
