#include "models/partitions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <set>

namespace swarmagg {
namespace {

TEST(Partitions, CountsMatchThePartitionNumbers) {
  const std::pair<int, std::size_t> known[] = {{1, 1},   {2, 2},    {3, 3},    {5, 7},
                                               {10, 42}, {20, 627}, {30, 5604}};
  for (const auto& [n, count] : known) {
    EXPECT_EQ(integer_partitions(n).size(), count) << "N = " << n;
    EXPECT_EQ(partition_count(n), static_cast<long long>(count)) << "N = " << n;
  }
}

// p(405) still fits a long long; from 406 on the count saturates instead of wrapping (a
// wrapped count once passed the model's size check and listed states until memory ran out).
TEST(Partitions, CountsBeyondALongLongSaturate) {
  EXPECT_EQ(partition_count(100), 190569292LL);
  EXPECT_LT(partition_count(405), std::numeric_limits<long long>::max());
  EXPECT_GT(partition_count(405), partition_count(404));
  EXPECT_EQ(partition_count(405), 9147679068859117602LL);  // p(405), OEIS A000041
  for (const int n : {406, 420, 1000, 1000000})
    EXPECT_EQ(partition_count(n), std::numeric_limits<long long>::max()) << "N = " << n;
}

TEST(Partitions, EachIsADistinctDecreasingPartitionOfN) {
  const auto partitions = integer_partitions(12);
  std::set<Partition> distinct(partitions.begin(), partitions.end());
  EXPECT_EQ(distinct.size(), partitions.size());
  for (const Partition& p : partitions) {
    EXPECT_EQ(std::accumulate(p.begin(), p.end(), 0), 12);
    EXPECT_TRUE(std::is_sorted(p.begin(), p.end(), std::greater<>()));
  }
  EXPECT_EQ(partitions.front(), Partition{12});
  EXPECT_EQ(partitions.back(), Partition(12, 1));
}

TEST(Partitions, LabelsAndDerivedQuantities) {
  const Partition p{3, 1, 1};
  EXPECT_EQ(partition_label(p), "3+1+1");
  EXPECT_EQ(free_agents(p), 2);
  EXPECT_EQ(aggregate_count(p), 1);
  EXPECT_EQ(largest_aggregate(p), 3);
  const Partition free{1, 1};
  EXPECT_EQ(aggregate_count(free), 0);
  EXPECT_EQ(largest_aggregate(free), 0);  // a single agent is not an aggregate
  EXPECT_EQ(partition_label(Partition{10, 10}), "10+10");
}

}  // namespace
}  // namespace swarmagg
