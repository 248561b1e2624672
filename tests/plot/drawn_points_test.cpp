// Long curves are drawn from evenly spaced points within a limit, always with their ends.
#include "plot/drawn_points.hpp"

#include <gtest/gtest.h>

#include "config/world_loader.hpp"
#include "models/output_grid.hpp"

namespace swarmagg {
namespace {

TEST(DrawnPoints, ACurveWithinTheLimitIsDrawnWhole) {
  for (const std::size_t count : {std::size_t{1}, std::size_t{7}, kMostDrawnPoints}) {
    const std::vector<std::size_t> indices = drawn_indices(count);
    ASSERT_EQ(indices.size(), count);
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(indices[i], i);
  }
  EXPECT_TRUE(drawn_indices(0).empty());
}

// 10^6 + 1 points (10^7 steps recorded every 10, and step 0): every 101st (every 100th would
// give 10,001) and the last.
TEST(DrawnPoints, ALongerCurveKeepsEveryKthPointAndTheLastWithinTheLimit) {
  const std::vector<std::size_t> indices = drawn_indices(1'000'001);
  ASSERT_LE(indices.size(), kMostDrawnPoints);
  EXPECT_EQ(indices.size(), 9902u);  // 0, 101, ..., 999,900, then 1,000,000
  EXPECT_EQ(indices[1], 101u);
  EXPECT_EQ(indices[indices.size() - 2], 999'900u);
  EXPECT_EQ(indices.back(), 1'000'000u);
  for (const std::size_t count : {kMostDrawnPoints + 1, 2 * kMostDrawnPoints + 1}) {
    const std::vector<std::size_t> some = drawn_indices(count);
    EXPECT_LE(some.size(), kMostDrawnPoints) << count;
    EXPECT_GT(some.size(), kMostDrawnPoints / 2) << count;
    EXPECT_EQ(some.front(), 0u);
    EXPECT_EQ(some.back(), count - 1) << count;
  }
}

// The steps a run records (every 10th of 250,005 steps, and the last): the filter keeps those
// at the drawn indices, the first and the last among them.
TEST(DrawnPoints, TheStepsDrawnAreTheRecordedStepsAtTheDrawnIndices) {
  const WorldSpec world =
      load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml",
                 {"run.duration=25000.5", "run.record_every=10"});
  const std::vector<std::int64_t> grid = record_grid(world);
  ASSERT_EQ(grid.size(), 25'002u);
  const StepFilter drawn = drawn_steps(world);
  ASSERT_TRUE(drawn);
  std::vector<std::int64_t> kept;
  for (std::int64_t step = 0; step <= world.steps(); ++step) {
    if (drawn(step)) kept.push_back(step);
  }
  std::vector<std::int64_t> expected;
  for (const std::size_t i : drawn_indices(grid.size())) expected.push_back(grid[i]);
  EXPECT_EQ(kept, expected);
  EXPECT_EQ(kept.front(), 0);
  EXPECT_EQ(kept.back(), 250'005);
  EXPECT_LE(kept.size(), kMostDrawnPoints);
}

TEST(DrawnPoints, AShortRunIsDrawnWholeWithoutAFilter) {
  const WorldSpec world =
      load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml", {});
  EXPECT_FALSE(drawn_steps(world));
}

}  // namespace
}  // namespace swarmagg
