// The NOA error of a run's model: the means per step read row by row, and the RMSE over the
// steps the simulation and the model share, checked against hand-computed values.
#include "analysis/noa_error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "analysis/step_series.hpp"
#include "core/errors.hpp"
#include "models/sample_statistics.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::filesystem::path written(const testing::ScratchDir& dir, const std::string& name,
                              const std::string& text) {
  const auto file = dir.path() / name;
  std::ofstream(file) << text;
  return file;
}

std::vector<std::int64_t> steps_of(const std::vector<StepMean>& means) {
  std::vector<std::int64_t> steps;
  for (const StepMean& m : means) steps.push_back(m.step);
  return steps;
}

TEST(StepMeans, GroupsReplicatesByStepInAnyRowOrder) {
  const testing::ScratchDir dir("noa-error");
  // Replicate 2 records a step the others lack, out of order, and misses step 10.
  const auto file = written(dir, "t.csv",
                            "replicate,step,time,noa\n"
                            "0,0,0,1\n0,10,1,2\n0,20,2,3\n"
                            "1,0,0,5\n1,10,1,6\n1,20,2,7\n"
                            "2,20,2,9\n2,5,0.5,8\n2,0,0,4\n");
  const std::vector<StepMean> means = read_step_means(file, "noa");
  EXPECT_THAT(steps_of(means), ::testing::ElementsAre(0, 5, 10, 20));
  EXPECT_EQ(means[0].count, 3u);
  EXPECT_DOUBLE_EQ(means[0].mean(), 10.0 / 3.0);
  EXPECT_EQ(means[1].mean(), 8.0);
  EXPECT_EQ(means[2].mean(), 4.0);
  EXPECT_DOUBLE_EQ(means[3].mean(), 19.0 / 3.0);
}

TEST(StepMeans, EqualTheMeansOfTheValuesBitForBit) {
  // Values whose sum depends on the order they are added in: the means must be those of the
  // series read whole (sample_mean of the values in file order), not merely close.
  StepMeans means;
  const std::vector<double> values{0.1, 1e16, -1e16, 0.7, 1.0 / 3.0};
  for (const double v : values) means.add(40, v);
  ASSERT_EQ(means.means().size(), 1u);
  EXPECT_EQ(means.means()[0].mean(), sample_mean(values));
}

// The same file is refused whether read whole (read_step_series) or a mean per step.
TEST(StepMeans, ADamagedTimeCellIsRefusedAsTheSeriesRefusesIt) {
  const testing::ScratchDir dir("noa-error");
  const auto file = written(dir, "t.csv", "replicate,step,time,noa\n0,0,0,1\n0,10,x,2\n");
  const auto message = HasSubstr(file.string() + ":3: column 'time'");
  EXPECT_THAT([&] { read_step_series(file, "noa"); }, ThrowsMessage<InputError>(message));
  EXPECT_THAT([&] { read_step_means(file, "noa"); }, ThrowsMessage<InputError>(message));
  const auto no_time = written(dir, "u.csv", "replicate,step,noa\n0,0,1\n");
  EXPECT_THROW(read_step_series(no_time, "noa"), InputError);
  EXPECT_THROW(read_step_means(no_time, "noa"), InputError);
}

TEST(NoaError, RmseOverTheSharedStepsOnly) {
  const testing::ScratchDir dir("noa-error");
  const auto simulation = written(dir, "sim.csv",
                                  "replicate,step,time,noa\n"
                                  "0,0,0,10\n0,10,1,8\n0,20,2,6\n0,30,3,5\n"
                                  "1,0,0,10\n1,10,1,6\n1,20,2,4\n1,30,3,5\n");
  // The model misses step 20 and records step 15, which the simulation lacks.
  const auto model = written(dir, "model.csv",
                             "replicate,step,time,noa\n"
                             "0,0,0,10\n0,10,1,4\n0,15,1.5,3\n0,30,3,1\n");
  // Means 10, 7, 5, 5 against 10, 4, -, 1 at steps 0, 10, 30: sqrt((0 + 9 + 16) / 3).
  const double expected = std::sqrt(25.0 / 3.0);
  EXPECT_DOUBLE_EQ(noa_rmse(read_noa_means(simulation), read_noa_means(model)), expected);
  EXPECT_EQ(noa_rmse(read_noa_means(simulation), read_noa_means(model)),
            noa_rmse(read_noa_series(simulation), read_noa_series(model)));
}

TEST(NoaError, NoSharedStepIsAnError) {
  const std::vector<StepMean> simulation{{0, 1.0, 1}, {10, 2.0, 1}};
  const std::vector<StepMean> model{{5, 1.0, 1}, {15, 2.0, 1}};
  EXPECT_THROW(noa_rmse(simulation, model), std::runtime_error);
}

}  // namespace
}  // namespace swarmagg
