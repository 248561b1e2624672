#include "rates/rate_recorder.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace swarmagg {
namespace {

TEST(RateRecorder, LeavesOutTheFirstDecisionAndPairsEachStateWithTheNextStepsEvents) {
  // 6 agents, 4 steps. After step 1 (the first decision) one pair exists and 1 creation and
  // 0 growths were counted; then a growth into 2 (step 2), a creation (step 3), nothing.
  RateRecorder recorder(6, 4);
  std::vector<std::uint64_t> growths(7, 0);
  const std::vector<std::int32_t> none, pair{2}, triple{3}, triple_pair{3, 2};
  recorder.observe(0, 6, none, 0, growths);
  recorder.observe(1, 4, pair, 1, growths);  // exposure y = 4: 6 pairs, y n_2 = 4
  growths[2] = 1;
  recorder.observe(2, 3, triple, 1, growths);       // y = 3: 3 pairs, y n_3 = 3
  recorder.observe(3, 1, triple_pair, 2, growths);  // y = 1: 0 pairs, y n_3 = y n_2 = 1
  recorder.observe(4, 1, triple_pair, 2, growths);  // last: no exposure
  const RateTally tally = recorder.finish();
  EXPECT_EQ(tally.replicates, 1);
  EXPECT_EQ(tally.steps, 3u);
  EXPECT_EQ(tally.creations, 1u);  // the first decision's pair left out
  EXPECT_EQ(tally.growths[2], 1u);
  EXPECT_EQ(tally.pair_steps, 6u + 3u + 0u);
  EXPECT_EQ(tally.searcher_aggregate_steps[2], 4u + 1u);
  EXPECT_EQ(tally.searcher_aggregate_steps[3], 3u + 1u);
  EXPECT_EQ(tally.aggregate_steps[3], 2u);
  EXPECT_EQ(tally.initial_aggregates[2], 1u);
  EXPECT_EQ(tally.initial_aggregates[3], 0u);

  RateTally merged(6);
  merged.merge(tally);
  merged.merge(tally);
  EXPECT_EQ(merged.replicates, 2);
  EXPECT_EQ(merged.pair_steps, 18u);
  EXPECT_EQ(merged.growths[2], 2u);
}

}  // namespace
}  // namespace swarmagg
