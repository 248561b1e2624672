#include "reproduce/timeout_series.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

ReproduceOptions paper_options() {
  ReproduceOptions options;
  options.worlds = std::filesystem::path(SWARMAGG_SOURCE_DIR) / "worlds" / "paper";
  options.quick = true;
  return options;
}

TEST(TimeoutSeries, EveryWorldRunsEveryTimeoutInTheReportsOrder) {
  const std::vector<TimeoutRun> runs = timeout_runs();
  ASSERT_EQ(runs.size(), std::size(kTimeoutWorlds) * std::size(kLeaveTimeouts));
  EXPECT_EQ(runs.front().world, kTimeoutWorlds[0]);
  EXPECT_EQ(runs.front().leave_timeout, kLeaveTimeouts[0]);
  EXPECT_EQ(runs.back().world, kTimeoutWorlds[std::size(kTimeoutWorlds) - 1]);
}

// The paper worlds wait 10 tu before leaving: that point is the figure's own run.
TEST(TimeoutSeries, OnlyThePapersOwnTimeoutAtThePapersLengthIsTheFiguresRun) {
  const ReproduceOptions options = paper_options();
  for (const char* world : kTimeoutWorlds) {
    EXPECT_TRUE(is_paper_run(options, {world, 10.0})) << world;
    EXPECT_FALSE(is_paper_run(options, {world, 20.0})) << world;
    EXPECT_FALSE(is_paper_run(options, {world, 50.0})) << world;
  }
  ReproduceOptions shorter = options;
  shorter.timeout_duration = 1000.0;
  EXPECT_FALSE(is_paper_run(shorter, {kTimeoutWorlds[0], 10.0}));
}

TEST(TimeoutSeries, APointsWorldChangesOnlyItsTimeoutAndName) {
  const WorldSpec world = timeout_world(paper_options(), {kTimeoutWorlds[0], 30.0});
  EXPECT_EQ(world.name, std::string(kTimeoutWorlds[0]) + "-timeout-30");
  EXPECT_EQ(world.controller.leave_timeout, 30.0);
}

}  // namespace
}  // namespace swarmagg
