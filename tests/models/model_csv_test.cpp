#include "models/model_csv.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "output/timeseries_csv.hpp"

namespace swarmagg {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

ModelRow row(int replicate, std::int64_t step, double noa) {
  ModelRow r;
  r.replicate = replicate;
  r.step = step;
  r.noa = noa;
  return r;
}

TEST(ModelCsv, ExpectedRowsAndStationaryValuesAreTidy) {
  VariantPrediction soysal{.model = "soysal", .variant = "peripheral", .series = {row(0, 3, 1.5)}};
  soysal.series[0].searching = 2.25;
  soysal.series[0].waiting = 0.75;  // N - searching: left out of model.csv
  soysal.extra.push_back({"partition:3+1+1", 3, 0.125});
  soysal.extra.push_back({"stationary:3+1+1", std::nullopt, 0.5});
  const auto lines = lines_of(model_csv({soysal}, 0.1));
  const std::vector<std::string> expected{
      "model,variant,step,time,quantity,value",   "soysal,peripheral,3,0.3,noa,1.5",
      "soysal,peripheral,3,0.3,searching,2.25",   "soysal,peripheral,3,0.3,partition:3+1+1,0.125",
      "soysal,peripheral,,,stationary:3+1+1,0.5",
  };
  EXPECT_EQ(lines, expected);
}

TEST(ModelCsv, StochasticVariantsGiveReplicateStatistics) {
  VariantPrediction stochastic{
      .model = "bayindir",
      .variant = "collision-stochastic",
      .stochastic = true,
      .series = {row(0, 10, 1), row(0, 20, 4), row(1, 10, 3), row(1, 20, 4)}};
  for (ModelRow& r : stochastic.series) {
    r.largest = 2 * r.replicate;  // mean and sd only
    r.creations = 5;              // per replicate in the timeseries files only
  }
  const auto lines = lines_of(model_csv({stochastic}, 0.1));
  ASSERT_EQ(lines.size(), 1u + 2 * (7 + 2));
  EXPECT_EQ(lines[1], "bayindir,collision-stochastic,10,1,noa,2");
  EXPECT_EQ(lines[2], "bayindir,collision-stochastic,10,1,noa:sd,1.4142135623730951");
  EXPECT_EQ(lines[3], "bayindir,collision-stochastic,10,1,noa:min,1");
  EXPECT_EQ(lines[4], "bayindir,collision-stochastic,10,1,noa:q25,1.5");
  EXPECT_EQ(lines[5], "bayindir,collision-stochastic,10,1,noa:median,2");
  EXPECT_EQ(lines[7], "bayindir,collision-stochastic,10,1,noa:max,3");
  EXPECT_EQ(lines[8], "bayindir,collision-stochastic,10,1,largest,1");
  EXPECT_EQ(lines[9], "bayindir,collision-stochastic,10,1,largest:sd,1.4142135623730951");
  EXPECT_EQ(lines[11], "bayindir,collision-stochastic,20,2,noa:sd,0");
}

TEST(ModelCsv, TimeseriesHasTheSimulationColumns) {
  VariantPrediction expected{
      .model = "bayindir", .variant = "original", .series = {row(0, 0, 0), row(0, 30, 7.5)}};
  expected.series[1].creations = 9;
  const auto lines = lines_of(model_timeseries_csv(expected, 0.1));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "replicate,step,time,noa,searching,waiting,leaving,approaching,largest,creations,"
            "growths,dissipations,shrinks,encounters");
  EXPECT_EQ(lines[0], kTimeseriesHeader);  // the simulation's own header
  EXPECT_EQ(lines[2], "0,30,3,7.5,,,,,,9,,,,");
}

}  // namespace
}  // namespace swarmagg
