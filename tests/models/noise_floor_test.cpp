#include "models/noise_floor.hpp"

#include <gtest/gtest.h>

#include "models/bayindir_expected.hpp"
#include "models/chain_distribution.hpp"
#include "models/model_test_worlds.hpp"
#include "models/output_grid.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {
namespace {

using testing::bayindir_world;
using testing::soysal_world;

// N = 5 Soysal chain, leaving fast enough (p0 = 2e-4) that a run of 10^5 steps visits every
// partition many times; the run-averaged law is taken as the stationary one (the chain
// starts there), so the floor is the sampling noise of the time fractions alone.
struct SoysalCase {
  WorldSpec world = soysal_world(5, 150.0, 2e-4);
  PartitionChain chain = build_partition_chain(soysal_rates(world, LeavingVariant::Peripheral));
  Eigen::VectorXd law = stationary_distribution(chain.generator);
  ChainRun run{.start = law, .start_step = 0, .steps = 100000};

  double floor(int replicates) const {
    return partition_noise_floor(chain, run, law, replicates, 7, noise_floor_stream("test"));
  }
};

TEST(NoiseFloor, ChainTimeFractionsFormADistribution) {
  const SoysalCase c;
  const Eigen::VectorXd fractions = chain_time_fractions(c.chain, c.run, 7, 0, 1);
  EXPECT_NEAR(fractions.sum(), 1.0, 1e-12);
  EXPECT_GE(fractions.minCoeff(), 0.0);
  EXPECT_GT((fractions.array() > 0.0).count(), 1);  // it moved
}

TEST(NoiseFloor, PartitionFloorIsSmallAndShrinksWithReplicates) {
  const SoysalCase c;
  const double few = c.floor(4), many = c.floor(64);
  EXPECT_GT(few, 0.0);
  EXPECT_LT(few, 0.2);
  // Sampling noise falls as 1 / sqrt(replicates): 16 times the replicates, a quarter.
  EXPECT_LT(many, 0.5 * few);
}

TEST(NoiseFloor, IsDeterministic) {
  const SoysalCase c;
  EXPECT_EQ(c.floor(3), c.floor(3));
}

TEST(NoiseFloor, NoaFloorIsSmallAndShrinksWithReplicates) {
  const WorldSpec world = bayindir_world(60, 0.001, true, true);
  const BayindirRates rates = bayindir_rates(world, CreationVariant::Collision);
  std::vector<std::int64_t> grid;
  for (std::int64_t step = 0; step <= 20000; step += 500) grid.push_back(step);
  const double final_noa = *bayindir_expected_series(rates, grid).back().noa;
  const double few = noa_noise_floor(rates, grid, {}, 4, 3, 11, 10);
  const double many = noa_noise_floor(rates, grid, {}, 64, 3, 11, 10);
  EXPECT_GT(few, 0.0);
  EXPECT_LT(few, 0.1 * final_noa);
  EXPECT_LT(many, 0.6 * few);
}

}  // namespace
}  // namespace swarmagg
