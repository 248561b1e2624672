#include "models/chain_distribution.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

PartitionChain chain_of(const WorldSpec& world, LeavingVariant variant = LeavingVariant::Original) {
  return build_partition_chain(soysal_rates(world, variant));
}

TEST(ChainDistribution, TwoAgentsFollowTheTwoStateClosedForm) {
  // States (2) and (1,1): pairing at rate a = P_e(1), dissolving at b = L(2) per step.
  // P(paired after k steps | free at 0) = a/(a+b) (1 - exp(-(a+b) k)).
  const SoysalRates rates = soysal_rates(testing::soysal_world(2, 150.0), LeavingVariant::Original);
  const PartitionChain chain = build_partition_chain(rates);
  ASSERT_EQ(chain.states.size(), 2u);
  const int paired = chain.states[0] == Partition{2} ? 0 : 1;
  const double a = rates.pair_up, b = rates.leave[2];
  const std::vector<std::int64_t> steps{0, 1, 1000, 12345, 100000, 100000000};
  const Eigen::MatrixXd distributions =
      transient_distributions(chain.generator, chain.all_free, steps);
  for (std::size_t j = 0; j < steps.size(); ++j) {
    const double k = static_cast<double>(steps[j]);
    const double expected = a / (a + b) * -std::expm1(-(a + b) * k);
    EXPECT_NEAR(distributions(static_cast<Eigen::Index>(j), paired), expected,
                1e-12 * std::max(expected, 1e-300) + 1e-17)
        << "k " << steps[j];
  }
}

TEST(ChainDistribution, DistributionsSumToOneAndStayNonNegative) {
  for (const LeavingVariant variant : {LeavingVariant::Original, LeavingVariant::Peripheral}) {
    const PartitionChain chain = chain_of(testing::soysal_world(10, 212.0), variant);
    const std::vector<std::int64_t> steps{0, 10, 1000, 100000, 10000000, 100000000};
    const Eigen::MatrixXd distributions =
        transient_distributions(chain.generator, chain.all_free, steps);
    for (Eigen::Index j = 0; j < distributions.rows(); ++j) {
      EXPECT_NEAR(distributions.row(j).sum(), 1.0, 1e-12);
      EXPECT_GE(distributions.row(j).minCoeff(), 0.0);
    }
    const Eigen::VectorXd stationary = stationary_distribution(chain.generator);
    EXPECT_NEAR(stationary.sum(), 1.0, 1e-12);
    EXPECT_GE(stationary.minCoeff(), 0.0);
  }
}

// expm(Q) by its Taylor series, accurate here because ||Q|| < 3e-3 (the 7th term < 1e-18).
Eigen::MatrixXd taylor_step(const Generator& generator) {
  const Eigen::MatrixXd q(generator);
  Eigen::MatrixXd sum = Eigen::MatrixXd::Identity(q.rows(), q.cols()), term = sum;
  for (int k = 1; k <= 6; ++k) {
    term = term * q / k;
    sum += term;
  }
  return sum;
}

TEST(ChainDistribution, EqualsTheMatrixExponentialStepByStep) {
  const PartitionChain chain = chain_of(testing::soysal_world(5, 150.0, 2e-3));
  const std::vector<std::int64_t> steps{0, 1, 7, 1000, 5};  // any order
  const Eigen::MatrixXd computed = transient_distributions(chain.generator, chain.all_free, steps);
  const Eigen::MatrixXd one_step = taylor_step(chain.generator);
  for (std::size_t j = 0; j < steps.size(); ++j) {
    Eigen::RowVectorXd distribution = Eigen::RowVectorXd::Unit(one_step.rows(), chain.all_free);
    for (std::int64_t k = 0; k < steps[j]; ++k) distribution = distribution * one_step;
    EXPECT_LT((computed.row(static_cast<Eigen::Index>(j)) - distribution).cwiseAbs().maxCoeff(),
              1e-13)
        << "k " << steps[j];
  }
}

TEST(ChainDistribution, AbsorbingPairFollowsItsClosedForm) {
  // Nobody leaves: (1,1) -> (2) at rate a, so P(paired after k steps) = 1 - exp(-a k); no
  // stationary shortcut applies, so this covers long uniformization series.
  WorldSpec world = testing::soysal_world(2, 150.0);
  world.controller.leave = false;
  const SoysalRates rates = soysal_rates(world, LeavingVariant::Original);
  const PartitionChain chain = build_partition_chain(rates);
  const std::vector<std::int64_t> steps{10, 1000, 20000, 100000};
  const Eigen::MatrixXd distributions =
      transient_distributions(chain.generator, chain.all_free, steps);
  for (std::size_t j = 0; j < steps.size(); ++j) {
    const double paired = -std::expm1(-rates.pair_up * static_cast<double>(steps[j]));
    EXPECT_NEAR(distributions(static_cast<Eigen::Index>(j), 0), paired, 1e-13) << steps[j];
  }
}

// N = 2 and N = 3 are birth-death chains, so detailed balance holds:
// pi(2)/pi(1,1) = P_e(1)/L(2); pi(2,1)/pi(1,1,1) = 3 P_e(1)/L(2); pi(3)/pi(2,1) = P_e(2)/L(3).
TEST(ChainDistribution, StationaryDetailedBalanceForTwoAndThreeAgents) {
  for (const LeaveLaw law : {LeaveLaw::Constant, LeaveLaw::Inverse, LeaveLaw::InverseSquare}) {
    const WorldSpec two = testing::soysal_world(2, 150.0, 2e-5, law);
    const SoysalRates r2 = soysal_rates(two, LeavingVariant::Peripheral);
    const PartitionChain c2 = build_partition_chain(r2);
    const Eigen::VectorXd pi2 = stationary_distribution(c2.generator);
    // Reverse lexicographic order: (2), (1,1).
    EXPECT_NEAR(pi2(0) / pi2(1), r2.pair_up / r2.leave[2], 1e-12 * pi2(0) / pi2(1));

    const WorldSpec three = testing::soysal_world(3, 150.0, 2e-5, law);
    const SoysalRates r3 = soysal_rates(three, LeavingVariant::Original);
    const PartitionChain c3 = build_partition_chain(r3);
    const Eigen::VectorXd pi3 = stationary_distribution(c3.generator);  // (3), (2,1), (1,1,1)
    const double pair_ratio = 3 * r3.pair_up / r3.leave[2];
    const double join_ratio = r3.join[2] / r3.leave[3];
    EXPECT_NEAR(pi3(1) / pi3(2), pair_ratio, 1e-12 * pair_ratio);
    EXPECT_NEAR(pi3(0) / pi3(1), join_ratio, 1e-12 * join_ratio);
  }
}

TEST(ChainDistribution, StationarySolvesBalanceAndIsTheLongRunLimit) {
  const PartitionChain chain = chain_of(testing::soysal_world(10, 212.0));
  const Eigen::VectorXd stationary = stationary_distribution(chain.generator);
  const Eigen::RowVectorXd flow = stationary.transpose() * Eigen::MatrixXd(chain.generator);
  // Every state's inflow balances its outflow: |(pi Q)_j| relative to pi_j * exit rate_j.
  for (Eigen::Index j = 0; j < flow.size(); ++j) {
    EXPECT_LE(std::abs(flow(j)), 1e-12 * stationary(j) * -chain.generator.coeff(j, j)) << j;
  }
  const Eigen::MatrixXd late =
      transient_distributions(chain.generator, chain.all_free, {100000000});
  EXPECT_LT((late.row(0) - stationary.transpose()).cwiseAbs().maxCoeff(), 1e-12);
  // The stationarity stop gives the same distributions as propagating all the way.
  const std::vector<std::int64_t> steps{1000000, 3000000, 100000000};
  const Eigen::MatrixXd stopped =
      transient_distributions(chain.generator, chain.all_free, steps, stationary);
  const Eigen::MatrixXd propagated =
      transient_distributions(chain.generator, chain.all_free, steps);
  EXPECT_LT((stopped - propagated).cwiseAbs().maxCoeff(), 1e-13);
}

}  // namespace
}  // namespace swarmagg
