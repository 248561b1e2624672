#include "models/partition_chain.hpp"

#include <gtest/gtest.h>

#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

int index_of(const PartitionChain& chain, const Partition& partition) {
  for (std::size_t i = 0; i < chain.states.size(); ++i) {
    if (chain.states[i] == partition) return static_cast<int>(i);
  }
  return -1;
}

TEST(PartitionChain, GeneratorHasTheSpecRates) {
  const SoysalRates rates = soysal_rates(testing::soysal_world(5, 150.0), LeavingVariant::Original);
  const PartitionChain chain = build_partition_chain(rates);
  ASSERT_EQ(chain.states.size(), 7u);
  EXPECT_TRUE(chain.recurrent);
  EXPECT_EQ(chain.states[chain.all_free], Partition(5, 1));
  const Generator& q = chain.generator;
  const int free5 = chain.all_free, pair = index_of(chain, {2, 1, 1, 1});
  const int two_pairs = index_of(chain, {2, 2, 1}), three = index_of(chain, {3, 1, 1});
  const int three_two = index_of(chain, {3, 2});
  EXPECT_DOUBLE_EQ(q.coeff(free5, pair), 10 * rates.pair_up);      // f(f-1)/2 = 10
  EXPECT_DOUBLE_EQ(q.coeff(pair, two_pairs), 3 * rates.pair_up);   // f = 3
  EXPECT_DOUBLE_EQ(q.coeff(pair, three), 3 * rates.join[2]);       // f c_2 = 3
  EXPECT_DOUBLE_EQ(q.coeff(pair, free5), rates.leave[2]);          // dissolve
  EXPECT_DOUBLE_EQ(q.coeff(two_pairs, pair), 2 * rates.leave[2]);  // c_2 = 2
  EXPECT_DOUBLE_EQ(q.coeff(three_two, two_pairs), rates.leave[3]);
  EXPECT_DOUBLE_EQ(q.coeff(free5, three), 0.0);
}

TEST(PartitionChain, RowsSumToZeroWithNonNegativeRates) {
  const PartitionChain chain = build_partition_chain(
      soysal_rates(testing::soysal_world(10, 212.0), LeavingVariant::Peripheral));
  ASSERT_EQ(chain.states.size(), 42u);
  const Eigen::MatrixXd q(chain.generator);
  for (Eigen::Index i = 0; i < q.rows(); ++i) {
    EXPECT_NEAR(q.row(i).sum(), 0.0, 1e-18);
    for (Eigen::Index j = 0; j < q.cols(); ++j) {
      if (i != j) {
        EXPECT_GE(q(i, j), 0.0);
      }
    }
  }
}

TEST(PartitionChain, RulesRestrictTheReachableStates) {
  WorldSpec world = testing::soysal_world(5, 150.0);
  world.controller.join = false;  // only pairs: (2,2,1), (2,1,1,1), (1,...,1)
  const PartitionChain pairs = build_partition_chain(soysal_rates(world, LeavingVariant::Original));
  EXPECT_EQ(pairs.states.size(), 3u);
  EXPECT_TRUE(pairs.recurrent);
  world.controller.join = true;
  world.controller.leave = false;
  const PartitionChain absorbing =
      build_partition_chain(soysal_rates(world, LeavingVariant::Original));
  EXPECT_EQ(absorbing.states.size(), 7u);
  EXPECT_FALSE(absorbing.recurrent);
}

}  // namespace
}  // namespace swarmagg
