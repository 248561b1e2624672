#include "sweep/shard.hpp"

#include <gmock/gmock.h>

#include "core/errors.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using testing::SweepTest;

TEST(Shard, ParsesIOverN) {
  const Shard shard = parse_shard("2/3");
  EXPECT_EQ(shard.index, 2);
  EXPECT_EQ(shard.count, 3);
  EXPECT_EQ(shard.text(), "2/3");
  EXPECT_TRUE(parse_shard("1/1").whole());
}

TEST(Shard, RefusesAnythingElse) {
  for (const char* text : {"0/3", "4/3", "3", "/3", "1/", "a/b", "1/0", "-1/3", "1/3x", ""}) {
    EXPECT_THROW(parse_shard(text), InputError) << text;
  }
  EXPECT_THAT([] { parse_shard("4/3"); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("1 <= i <= n")));
}

TEST_F(SweepTest, ShardsPartitionTheRuns) {
  const auto all = expand_sweep(load_sweep(sweep_file(testing::kGridSweep)));
  std::vector<int> owner(all.size(), 0);
  for (int i = 1; i <= 4; ++i) {
    for (const SweepRun& run : shard_runs(all, Shard{i, 4})) {
      EXPECT_EQ(run.index % 4, i - 1);
      ++owner[static_cast<std::size_t>(run.index)];
    }
  }
  for (const int count : owner) EXPECT_EQ(count, 1);
}

}  // namespace
}  // namespace swarmagg
