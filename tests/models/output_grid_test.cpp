#include "models/output_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

TEST(OutputGrid, RecordGridIsTheSimulationsRecordedSteps) {
  WorldSpec world = testing::bayindir_world(10, 0.0, true, true);
  world.run.duration = 100.5;  // 1005 steps: recorded at 0, 10, ..., 1000 and the last
  world.run.record_every = 10;
  const auto grid = record_grid(world);
  ASSERT_EQ(grid.size(), 102u);
  EXPECT_EQ(grid[1], 10);
  EXPECT_EQ(grid[100], 1000);
  EXPECT_EQ(grid.back(), 1005);
}

TEST(OutputGrid, SparseGridCoversEarlyAndLateTimesOnTheRecordGrid) {
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.run.duration = 1e6;  // 1e7 steps
  world.run.record_every = 100;
  const auto grid = sparse_grid(world, 50);
  EXPECT_EQ(grid.front(), 0);
  EXPECT_EQ(grid[1], 100);  // the first log-spaced steps round up to one record interval
  EXPECT_EQ(grid.back(), 10000000);
  EXPECT_TRUE(std::is_sorted(grid.begin(), grid.end()));
  EXPECT_EQ(std::adjacent_find(grid.begin(), grid.end()), grid.end());
  EXPECT_GT(grid.size(), 70u);
  EXPECT_LE(grid.size(), 101u);
  for (const auto step : grid) EXPECT_EQ(step % 100, 0) << step;
}

TEST(OutputGrid, WalkGridAdvancesToEachRecordedStep) {
  std::vector<std::int64_t> advanced, recorded;
  walk_grid(
      std::vector<std::int64_t>{0, 2, 5}, [&](std::int64_t step) { advanced.push_back(step); },
      [&](std::int64_t step) { recorded.push_back(step); });
  EXPECT_EQ(recorded, (std::vector<std::int64_t>{0, 2, 5}));
  EXPECT_EQ(advanced, (std::vector<std::int64_t>{0, 1, 2, 3, 4}));  // 5 steps in all
}

// Progress comes in batches (its hook checks for Ctrl-C, too costly for every step) and adds
// up to every step taken.
TEST(OutputGrid, WalkGridReportsEveryStepInBatches) {
  std::vector<std::int64_t> reports;
  walk_grid(
      std::vector<std::int64_t>{0, 5000, 10000}, [](std::int64_t) {}, [](std::int64_t) {},
      [&](std::int64_t steps) { reports.push_back(steps); });
  EXPECT_EQ(reports, (std::vector<std::int64_t>{kWalkProgressBatch, kWalkProgressBatch,
                                                10000 - 2 * kWalkProgressBatch}));
}

}  // namespace
}  // namespace swarmagg
