#include "reproduce/report.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace swarmagg {
namespace {

RateEstimate mean_of(double value) {
  return {.events = 40, .exposure = 40.0, .rate = value, .low = value, .high = value};
}

// A figure whose run measured aggregates of sizes 2, 4, 8 and 16 packed as R1 = r 1.2 m^0.48
// (r = 1) with every member on the rim.
FigureResult measured_geometry(const std::string& figures, const std::string& world,
                               const std::vector<int>& sizes) {
  FigureResult result;
  result.figure = {.id = "fig" + figures, .figures = figures, .title = world, .worlds = {world}};
  result.worlds.emplace_back();
  result.worlds.back().name = world;
  for (const int m : sizes) {
    result.rates.push_back({"radius", m, mean_of(1.2 * std::pow(m, 0.48)), {}});
    result.rates.push_back({"rim", m, mean_of(m), {}});
  }
  return result;
}

std::string line_of(const std::string& text, const std::string& start) {
  const auto at = text.find(start);
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

TEST(Report, SetsTheFittedGeometryLawsAgainstThePapers) {
  const std::vector<FigureResult> results{measured_geometry("18", "packed", {2, 4, 8, 16}),
                                          measured_geometry("9", "pairs", {2})};
  const std::string report = report_markdown({"quick", "kinematic", 1.0}, results, {});
  // R1: exactly the paper's law. Rim = m: log(m / pi + 1) is no power law, so its fit has
  // a spread, and the rim share at the largest size is 1.
  const std::string row =
      line_of(report, "| 18 | packed | 4 | 1.2 [1.2, 1.2] | 0.48 [0.48, 0.48] |");
  ASSERT_FALSE(row.empty()) << report;
  EXPECT_NE(row.find("| 1 (m = 16) |"), std::string::npos) << row;
  EXPECT_TRUE(line_of(report, "| 9 | pairs |").empty());  // pairs only: no fit
}

TEST(Report, SaysSoWhenNoExperimentHasEnoughSizes) {
  const std::string report =
      report_markdown({"quick", "kinematic", 1.0}, {measured_geometry("9", "pairs", {2, 3})}, {});
  EXPECT_NE(report.find("No experiment formed aggregates of enough sizes"), std::string::npos);
}

// The "why" table explains misses only: where a paper variant is within 2x its floor there is
// none, and a term whose interval holds the model's value is no deviation.
TEST(Report, WhyTheModelsMissNamesNoMissAndNoNoise) {
  FigureResult fits = measured_geometry("18", "fits", {2, 4, 8, 16});
  NoaComparison c;
  c.errors = {{"original", 1.5, 1.0},
              {"collision", 3.0, 1.0},
              {"collision-paper", 9.0, 1.0},
              {"measured", 1.0, 1.0}};
  c.simulation = {.steps = {0}, .times = {0.0}, .values = {{10.0}}};
  fits.noa = c;
  fits.rates.push_back({"growth",
                        3,
                        {.events = 40, .exposure = 1.0, .rate = 1.1, .low = 0.8, .high = 1.4},
                        {{"bayindir", "collision", 1.0}}});
  FigureResult misses = fits;
  misses.figure.figures = "19";
  misses.worlds.back().name = "misses";
  misses.noa->errors[0].error = 5.0;
  misses.noa->errors[1].error = 6.0;
  const std::string report = report_markdown({"quick", "kinematic", 1.0}, {fits, misses}, {});
  const std::string fit_row = line_of(report, "| 18 | fits | none outside its 95% CI | - |");
  EXPECT_NE(fit_row.find("no miss: original is within 2x its noise floor"), std::string::npos)
      << report;
  const std::string miss_row = line_of(report, "| 19 | misses | none outside its 95% CI |");
  EXPECT_NE(miss_row.find("the terms: measured terms fix most of the error"), std::string::npos)
      << miss_row;
}

}  // namespace
}  // namespace swarmagg

namespace swarmagg {
namespace {

// The partition table's "better" column: a difference within the noise floor is no ranking.
TEST(Report, ABetterVariantWithinTheNoiseFloorIsSaidToBe) {
  FigureResult r;
  r.figure = {.id = "fig25", .figures = "25", .title = "soysal", .worlds = {"soysal-5"}};
  r.worlds.emplace_back();
  r.worlds.back().name = "soysal-5";
  PartitionComparison c;
  c.models.resize(2);
  c.errors = {{"original", 0.27, 0.22}, {"peripheral", 0.35, 0.21}, {"returns", 0.19, 0.22}};
  r.partitions = c;
  const std::string report = report_markdown({"quick", "kinematic", 1.0}, {r}, {});
  EXPECT_NE(report.find("| returns (within noise of original) |"), std::string::npos) << report;
  r.partitions->errors[0].error = 0.6;
  r.partitions->errors[1].error = 0.5;
  EXPECT_NE(report_markdown({"quick", "kinematic", 1.0}, {r}, {}).find("| returns |"),
            std::string::npos);
}

}  // namespace
}  // namespace swarmagg
