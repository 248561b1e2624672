#include "models/kinetic_rate.hpp"

#include <gtest/gtest.h>

#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

// Hand values: 180x180 arena (A = 32400), s = 4, v = 1, dt = 0.1.
TEST(KineticRate, KappaValues) {
  EXPECT_DOUBLE_EQ(kappa_value(Kappa::Kinetic), 1.2732395447351628);  // 4/pi
  EXPECT_DOUBLE_EQ(kappa_value(Kappa::Maxwell), 1.4142135623730951);  // sqrt 2
}

TEST(KineticRate, EncounterRatePerTimeUnitOfThePaperCollisionCheck) {
  // Fig 7 setting, N = 100 on 540x540: Z = (4/pi) 4 * 1 * 100 * 99 / 291600.
  const PairRate rate = encounter_rate(Kappa::Kinetic, 4.0, 1.0, 540.0 * 540.0);
  EXPECT_NEAR(rate.at(100), 0.17290907397638014, 1e-15);
}

TEST(KineticRate, CollisionCreationUsesKappaAndOrderedPairs) {
  const WorldSpec world = testing::bayindir_world(150, 0.0, false, false);
  const PairRate rate = creation_per_step(world, CreationVariant::Collision);
  EXPECT_EQ(rate.pairs, PairCount::Ordered);
  EXPECT_NEAR(rate.coefficient, 1.5719006725125465e-05, 1e-19);
  EXPECT_NEAR(rate.at(150), 0.35131980030655413, 1e-14);  // k * 150 * 149
}

TEST(KineticRate, OriginalCreationIsSqrtTwoTimesYSquared) {
  WorldSpec world = testing::bayindir_world(150, 0.0, false, false);
  world.model.kappa = Kappa::Kinetic;  // the original variant ignores kappa
  const PairRate rate = creation_per_step(world, CreationVariant::Original);
  EXPECT_EQ(rate.pairs, PairCount::Squared);
  EXPECT_NEAR(rate.coefficient, 1.745942669596414e-05, 1e-19);
  EXPECT_NEAR(rate.at(150), 0.39283710065919314, 1e-14);  // k * 150^2
}

TEST(KineticRate, PaperFitIgnoresTheArea) {
  WorldSpec world = testing::bayindir_world(150, 0.0, false, false);
  world.model.kappa = Kappa::Paper;
  const PairRate small = creation_per_step(world, CreationVariant::Collision);
  world.arena.width = world.arena.height = 540.0;
  const PairRate large = creation_per_step(world, CreationVariant::Collision);
  EXPECT_NEAR(small.coefficient, 4.919003695210766e-06, 1e-20);  // sqrt2/1.15e5 * 4 * 1 * 0.1
  EXPECT_EQ(small.coefficient, large.coefficient);
  EXPECT_EQ(small.pairs, PairCount::Squared);
}

TEST(KineticRate, MaxwellKappaScalesTheKineticRate) {
  WorldSpec world = testing::bayindir_world(50, 0.0, false, false);
  const double kinetic = creation_per_step(world, CreationVariant::Collision).coefficient;
  world.model.kappa = Kappa::Maxwell;
  const double maxwell = creation_per_step(world, CreationVariant::Collision).coefficient;
  EXPECT_NEAR(maxwell / kinetic, 1.4142135623730951 / 1.2732395447351628, 1e-14);
}

TEST(KineticRate, ExpectedPairsNeverNegative) {
  const PairRate ordered{1.0, PairCount::Ordered};
  EXPECT_EQ(ordered.at(0.5), 0.0);  // E[y(y-1)] >= 0 even when E[y] < 1
  EXPECT_EQ(ordered.at(3.0), 6.0);
  EXPECT_EQ((PairRate{1.0, PairCount::Squared}.at(0.5)), 0.25);
}

}  // namespace
}  // namespace swarmagg
