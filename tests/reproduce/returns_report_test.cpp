#include "reproduce/returns_report.hpp"

#include <gtest/gtest.h>

#include "analysis/run_stationarity.hpp"
#include "analysis/step_series.hpp"

namespace swarmagg {
namespace {

RateRow counted(const std::string& term, int size, std::uint64_t events, double exposure) {
  return {term, size, {.events = events, .exposure = exposure}, {}};
}

// A Soysal figure whose paper variant misses (10x its floor) and whose measured variant fits.
FigureResult soysal_figure() {
  FigureResult r;
  r.figure = {.id = "fig26", .figures = "26-27", .title = "soysal", .worlds = {"soysal-10"}};
  r.worlds.emplace_back();
  r.worlds.back().name = "soysal-10";
  r.worlds.back().controller.leave = true;
  PartitionComparison c;
  c.errors = {{"original", 0.8, 0.08}, {"peripheral", 0.6, 0.07}, {"measured", 0.15, 0.1}};
  r.partitions = c;
  r.rates = {counted("return", 3, 90, 100.0), counted("return", 4, 290, 300.0),
             counted("return", 2, 1, 40.0), counted("join", 3, 100, 5.0),
             counted("join_new", 3, 20, 4.0)};
  return r;
}

TEST(ReturnsReport, PoolsReturnsFromAggregatesOfThreeOrMore) {
  const ReturnSummary s = pooled_returns(soysal_figure().rates);
  EXPECT_EQ(s.attempts, 400u);
  EXPECT_EQ(s.returns, 380u);
  EXPECT_DOUBLE_EQ(s.fraction(), 0.95);
  EXPECT_DOUBLE_EQ(returning_share_of_joins(soysal_figure().rates), 0.8);
}

// rates.csv times a size's returns only from 10 of them on: the mean time away is over the
// timed ones, and says how many those are when not all (it read as every return's).
TEST(ReturnsReport, TheMeanTimeAwaySaysWhichReturnsItCovers) {
  FigureResult r = soysal_figure();
  const auto timed = [](int size, std::uint64_t returns, double mean) {
    RateRow row = counted("return_time", size, returns, static_cast<double>(returns));
    row.estimate.rate = mean;
    return row;
  };
  r.rates.push_back(timed(3, 90, 10.0));
  r.rates.push_back(timed(4, 290, 20.0));
  EXPECT_DOUBLE_EQ(pooled_returns(r.rates).mean_time, (90 * 10.0 + 290 * 20.0) / 380.0);
  EXPECT_NE(why_models_miss_section({r}, {}).find("(mean time away 17.63 tu)"), std::string::npos)
      << why_models_miss_section({r}, {});
  r.rates.back() = counted("return_time", 4, 290, 290.0);  // too few to time, say
  const ReturnSummary partly = pooled_returns(r.rates);
  EXPECT_EQ(partly.timed, 90u);
  EXPECT_NE(why_models_miss_section({r}, {}).find("(mean time away 10 tu, over 90 of 380 returns)"),
            std::string::npos)
      << why_models_miss_section({r}, {});
}

TEST(ReturnsReport, EveryErrorStandsBesideItsFloor) {
  const std::string text = noise_floor_section({soysal_figure()}, {});
  EXPECT_NE(text.find("original 0.8 / 0.08 (10x)"), std::string::npos) << text;
  EXPECT_NE(text.find("measured 0.15 / 0.1 (1.5x)"), std::string::npos) << text;
}

TEST(ReturnsReport, WhyTheModelsMissFollowsTheNumbers) {
  const std::string text = why_models_miss_section({soysal_figure()}, {});
  EXPECT_NE(text.find("380 / 400 (0.95) LEAVE attempts"), std::string::npos) << text;
  EXPECT_NE(text.find("80 % of all joins"), std::string::npos) << text;
  EXPECT_NE(text.find("peripheral) is at 8.571x its floor (misses)"), std::string::npos) << text;
  EXPECT_NE(text.find("1.5x its floor (fits)"), std::string::npos) << text;
  EXPECT_NE(text.find("in 1 of 1 comparisons"), std::string::npos) << text;
}

// Where the replicates spread more than a variant's floor, the floor understates the
// simulation's noise: the error is given as a multiple of the spread too, and the table shows it.
TEST(ReturnsReport, AnErrorStandsBesideTheReplicatesSpreadWhereItExceedsTheFloor) {
  FigureResult r = soysal_figure();
  r.partitions->spread = 0.2;  // above every variant's floor (0.08, 0.07, 0.1)
  const std::string text = why_models_miss_section({r}, {});
  EXPECT_NE(text.find("(peripheral) is at 8.571x its floor (misses; 3x the replicates' spread)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("`measured` (measured q, new joins) at 1.5x its floor (fits; 0.75x the "
                      "replicates' spread)"),
            std::string::npos)
      << text;
  EXPECT_NE(noise_floor_section({r}, {}).find("(1.5x) | 0.2 |"), std::string::npos);
}

// The series' point at the worlds' own timeout is the figure's run: counted once, not twice.
TEST(ReturnsReport, TheFiguresOwnRunInTheSeriesIsJudgedOnce) {
  TimeoutPoint own{.world = "soysal-10", .agents = 10, .leave_timeout = 10.0};
  own.comparison = *soysal_figure().partitions;
  own.paper_run = true;
  TimeoutPoint longer = own;
  longer.leave_timeout = 20.0;
  longer.paper_run = false;
  longer.comparison.errors.back() = {"measured", 0.5, 0.1};
  const std::string text = why_models_miss_section({soysal_figure()}, {own, longer});
  EXPECT_NE(text.find("in 1 of 2 comparisons; it still misses in soysal-10 at timeout 20 (5x)"),
            std::string::npos)
      << text;
  // Without its figure (reproduce --only timeout-series) the series judges its own point.
  EXPECT_NE(why_models_miss_section({}, {own, longer}).find("in 1 of 2 comparisons"),
            std::string::npos);
}

// A run whose every replicate kept one NOA over the second half is no evidence of mixing:
// the table says so instead of "stationary".
TEST(ReturnsReport, ARunWithEveryNoaFixedIsNotCalledStationary) {
  FigureResult r = soysal_figure();
  r.trend = NoaTrend{.frozen = 10, .replicates = 10};
  EXPECT_NE(soysal_distribution_section({r}).find("NOA fixed (every replicate's NOA constant)"),
            std::string::npos);
  r.trend->frozen = 8;
  EXPECT_NE(soysal_distribution_section({r}).find("stationary, NOA constant in 8 of 10 replicates"),
            std::string::npos);
  // A second half of fewer than 2 recorded steps has no slope: not judged, not stationary.
  r.trend = second_half_trend(
      StepSeries{.steps = {0, 10}, .times = {0.0, 1.0}, .values = {{0.0, 0.0}, {3.0, 4.0}}});
  EXPECT_EQ(r.trend->replicates, 0);
  const std::string table = soysal_distribution_section({r});
  EXPECT_NE(table.find("not judged (fewer than 2 recorded steps in the second half)"),
            std::string::npos)
      << table;
  EXPECT_EQ(table.find("| stationary"), std::string::npos) << table;
  EXPECT_EQ(table.find("] stationary"), std::string::npos) << table;
}

// A run in which nobody tried to leave has no leavers to come back: said so, not "0 / 0 (0)".
TEST(ReturnsReport, ARunWithoutLeaveAttemptsSaysSo) {
  FigureResult r = soysal_figure();
  r.rates = {counted("join", 3, 100, 5.0)};
  const std::string text = why_models_miss_section({r}, {});
  EXPECT_NE(text.find("no agent tried to leave, so none came back"), std::string::npos) << text;
  EXPECT_EQ(text.find("0 / 0"), std::string::npos) << text;
}

}  // namespace
}  // namespace swarmagg
