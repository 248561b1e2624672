#include "models/initial_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/errors.hpp"
#include "model_test_worlds.hpp"

namespace swarmagg {
namespace {

TEST(InitialState, AnnulusQuadratureMatchesClosedForms) {
  // Two points uniform in a disc of radius R lie within R of each other with probability
  // 1 - 3 sqrt 3 / (4 pi); within 2R always.
  EXPECT_NEAR(annulus_distance_probability(0.0, 1.0, 1.0),
              1.0 - 3.0 * std::sqrt(3.0) / (4.0 * std::numbers::pi), 2e-4);
  EXPECT_NEAR(annulus_distance_probability(2.0, 4.0, 8.0), 1.0, 1e-9);
  EXPECT_NEAR(annulus_distance_probability(2.0, 4.0, 0.0), 0.0, 1e-9);
}

TEST(InitialState, FirstOrderIsTheCloseFractionOfAllPairs) {
  const WorldSpec world = testing::bayindir_world(400, 0.0, false, false, 460.0);
  const double q = placement_pair_probability(world);
  EXPECT_DOUBLE_EQ(q, std::numbers::pi * (16.0 - 4.0) / (460.0 * 460.0));
  const FirstDecision first = expected_first_decision(world);
  const double edges = 400.0 * 399.0 / 2.0 * q;
  // Greedy pairing loses an agent in every component of three: fewer pairs than close pairs.
  EXPECT_LT(first.pairs, edges);
  EXPECT_GT(first.pairs, 0.9 * edges);
  EXPECT_EQ(first.triples, 0.0);
}

TEST(InitialState, JoiningTurnsThreeAgentComponentsIntoTriples) {
  const WorldSpec apart = testing::bayindir_world(400, 0.0, false, false, 460.0);
  const WorldSpec joining = testing::bayindir_world(400, 0.0, true, false, 460.0);
  const FirstDecision pairs_only = expected_first_decision(apart);
  const FirstDecision with_joins = expected_first_decision(joining);
  EXPECT_GT(with_joins.triples, 0.0);
  // One aggregate per component either way.
  EXPECT_NEAR(with_joins.pairs + with_joins.triples, pairs_only.pairs, 1e-9);
}

TEST(InitialState, TheKeyChoosesTheStart) {
  WorldSpec world = testing::bayindir_world(100, 0.0, false, false);
  EXPECT_GT(start_aggregates(world, nullptr, nullptr).at(2), 0.0);
  world.model.initial_state = InitialState::AllSearching;
  EXPECT_TRUE(start_aggregates(world, nullptr, nullptr).empty());
  world.model.initial_state = InitialState::Measured;
  EXPECT_THROW(start_aggregates(world, nullptr, nullptr), InputError);
  MeasuredTerms measured;
  measured.initial = {{2, 3.5}};
  EXPECT_DOUBLE_EQ(start_aggregates(world, &measured, nullptr).at(2), 3.5);
  world.model.initial_state = InitialState::Placement;
  PlacementSample sample;
  sample.aggregates = std::vector<double>(101, 0.0);
  sample.aggregates[2] = 4.25;
  EXPECT_DOUBLE_EQ(start_aggregates(world, nullptr, &sample).at(2), 4.25);
  EXPECT_THROW(start_aggregates(world, nullptr, nullptr), std::logic_error);
  world.model.initial_state = InitialState::PlacementSecondOrder;
  world.robots.placement = {{1, 1, 0}, {3, 1, 0}};
  world.robots.count = 2;
  EXPECT_TRUE(
      start_aggregates(world, nullptr, nullptr).empty());  // given positions: no expectation
}

TEST(InitialState, OnlyWorldsWithAnAggregationModelStartFromASample) {
  WorldSpec world = testing::bayindir_world(100, 0.0, false, false);
  world.model.initial_state = InitialState::Placement;
  EXPECT_TRUE(starts_from_placement_sample(world));
  world.controller.type = "soysal";
  EXPECT_TRUE(starts_from_placement_sample(world));
  world.controller.type = "collision";
  EXPECT_FALSE(starts_from_placement_sample(world));
  EXPECT_TRUE(start_aggregates(world, nullptr, nullptr).empty());
  world.controller.type = "bayindir";
  world.model.initial_state = InitialState::AllSearching;
  EXPECT_FALSE(starts_from_placement_sample(world));
}

}  // namespace
}  // namespace swarmagg
