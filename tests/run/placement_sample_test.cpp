#include "run/placement_sample.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "config/world_loader.hpp"
#include "models/initial_state.hpp"
#include "models/predictions.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

WorldSpec example_world(const std::string& file, const std::vector<std::string>& overrides) {
  return load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/" + file, overrides);
}

// What runs measure: the aggregates by size after the first decision of each replicate (a
// stream of the world's seed the sample does not use), per replicate.
std::vector<std::vector<double>> measured_first_decisions(const WorldSpec& world, int replicates) {
  std::vector<std::vector<double>> counts;
  for (int index = 0; index < replicates; ++index) {
    Replicate replicate(world, index);
    replicate.step();
    std::vector<double> by_size(static_cast<std::size_t>(world.robots.count) + 1, 0.0);
    for (const std::int32_t size : replicate.aggregates().sizes())
      ++by_size[static_cast<std::size_t>(size)];
    counts.push_back(by_size);
  }
  return counts;
}

struct MeanAndError {
  double mean = 0.0;
  double error = 0.0;  // standard error of the mean
};

// Over replicates, of the aggregates whose size lies in [low, high].
MeanAndError over_replicates(const std::vector<std::vector<double>>& counts, int low, int high) {
  double sum = 0.0, square_sum = 0.0;
  for (const std::vector<double>& by_size : counts) {
    double x = 0.0;
    for (int m = low; m <= high && m < static_cast<int>(by_size.size()); ++m)
      x += by_size[static_cast<std::size_t>(m)];
    sum += x;
    square_sum += x * x;
  }
  const auto n = static_cast<double>(counts.size());
  const double mean = sum / n;
  return {mean, std::sqrt((square_sum / n - mean * mean) / (n - 1.0))};
}

double in_sample(const PlacementSample& sample, int low, int high) {
  double total = 0.0;
  for (int m = low; m <= high && m < static_cast<int>(sample.aggregates.size()); ++m)
    total += sample.aggregates[static_cast<std::size_t>(m)];
  return total;
}

TEST(PlacementSample, PlacementsDrawnShrinkWithTheSwarm) {
  EXPECT_EQ(placements_to_sample(20), 4096);
  EXPECT_EQ(placements_to_sample(400), 655);
  EXPECT_EQ(placements_to_sample(1000000), 8);
}

// compact.yaml's 400 agents on 100 x 100 start with 1.5 others within s each: far beyond the
// second-order formula, which puts every agent into a triple. The sample holds the runs'
// first decision there, size by size.
TEST(PlacementSample, MatchesTheFirstDecisionRunsMeasureInADenseWorld) {
  const WorldSpec world = example_world("compact.yaml", {"robots.count=200"});
  const PlacementSample sample = sample_placements(world, 2);
  ASSERT_EQ(sample.placements, placements_to_sample(200));
  const std::vector<std::vector<double>> runs = measured_first_decisions(world, 300);
  for (const auto& [low, high] : {std::pair{2, 2}, {3, 3}, {4, 5}, {6, 200}, {2, 200}}) {
    const MeanAndError measured = over_replicates(runs, low, high);
    EXPECT_NEAR(in_sample(sample, low, high), measured.mean, 4.0 * measured.error + 1e-9)
        << "sizes " << low << ".." << high;
  }
  // The NOA's standard error is the one of the sample's own placements.
  const MeanAndError noa = over_replicates(runs, 2, 200);
  const double expected_error = noa.error * std::sqrt(300.0 / sample.placements);
  EXPECT_NEAR(sample.noa_standard_error, expected_error, 0.3 * expected_error);
  // The formula's triples (third agents joining pairs) are several times too many here.
  EXPECT_GT(expected_first_decision(world).triples, 3.0 * in_sample(sample, 3, 3));
}

TEST(PlacementSample, IsTheSameForAnyThreadCount) {
  const WorldSpec world = example_world("demo.yaml", {"robots.count=300"});
  const PlacementSample one = sample_placements(world, 1);
  const PlacementSample two = sample_placements(world, 2);
  EXPECT_EQ(one.aggregates, two.aggregates);
  EXPECT_EQ(one.noa_standard_error, two.noa_standard_error);
}

// Large swarms are placed one at a time, each step on every thread: the same sample.
TEST(PlacementSample, IsTheSameForAnyThreadCountInALargeSwarm) {
  const WorldSpec world =
      example_world("demo.yaml", {"robots.count=70000", "arena.width=4100", "arena.height=4100"});
  const PlacementSample one = sample_placements(world, 1);
  EXPECT_EQ(one.placements, 8);
  EXPECT_GT(in_sample(one, 2, 70000), 1000.0);
  const PlacementSample two = sample_placements(world, 2);
  EXPECT_EQ(one.aggregates, two.aggregates);
}

TEST(PlacementSample, GivenPositionsAreOnePlacementWithACertainFirstDecision) {
  // Three agents in a row within s of the middle one (a pair, and the third joins it) and a
  // pair far away.
  WorldSpec world = example_world("demo.yaml", {});
  world.robots.placement = {{10, 10, 0}, {13, 10, 90}, {16.5, 10, 180}, {60, 60, 0}, {63, 60, 0}};
  world.robots.count = 5;
  const PlacementSample sample = sample_placements(world, 2);
  EXPECT_EQ(sample.placements, 1);
  EXPECT_EQ(sample.noa_standard_error, 0.0);
  EXPECT_EQ(sample.aggregates, (std::vector<double>{0, 0, 1, 1, 0, 0}));
  EXPECT_NE(placement_start_note(sample).find("aggregates: the given positions"), std::string::npos);
}

TEST(PlacementSample, IsTakenOnlyWhereTheModelsStartFromIt) {
  WorldSpec world = example_world("demo.yaml", {});
  EXPECT_TRUE(placement_start(world, 1).has_value());
  world.model.initial_state = InitialState::AllSearching;
  EXPECT_FALSE(placement_start(world, 1).has_value());
  // And every variant starts from it: its NOA at step 1 is the sample's.
  world.model.initial_state = InitialState::Placement;
  world.model.stochastic_replicates = 0;
  world.run.record_every = 1;
  world.run.duration = 1.0;
  const PlacementSample sample = sample_placements(world, 1);
  const std::vector<VariantPrediction> predictions = predict_world(world, nullptr, 1);
  ASSERT_FALSE(predictions.empty());
  for (const VariantPrediction& prediction : predictions) {
    ASSERT_EQ(prediction.series.at(1).step, 1);
    EXPECT_DOUBLE_EQ(*prediction.series.at(1).noa, in_sample(sample, 2, world.robots.count))
        << prediction.variant;
  }
}

WorldSpec paper_world(const std::string& file, const std::vector<std::string>& overrides) {
  return load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/paper/" + file, overrides);
}

// Small swarms keep each placement's partition; their mean sizes are the sample's.
TEST(PlacementSample, SmallSwarmsKeepTheDistributionOfPartitions) {
  const WorldSpec world =
      paper_world("soysal-10-constant.yaml", {"arena.width=40", "arena.height=40"});
  const PlacementSample sample = sample_placements(world, 2);
  double total = 0.0;
  std::vector<double> by_size(11, 0.0);
  for (const auto& [partition, probability] : sample.partitions) {
    int agents = 0;
    for (const int part : partition) {
      agents += part;
      if (part >= 2) by_size[static_cast<std::size_t>(part)] += probability;
    }
    EXPECT_EQ(agents, 10);
    total += probability;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_GT(sample.partitions.size(), 5u);
  for (std::size_t m = 2; m < by_size.size(); ++m)
    EXPECT_NEAR(by_size[m], sample.aggregates[m], 1e-12) << m;
  EXPECT_TRUE(sample_placements(paper_world("full-0.0005.yaml", {}), 2).partitions.empty());
}

// A certain pair starts the partition model in 2+1+1+1 for sure; independent Poisson counts
// of its mean (one pair) would put 0.4 there.
TEST(PlacementSample, ThePartitionModelStartsFromTheSampledPartitions) {
  WorldSpec world = paper_world("soysal-5-constant.yaml", {"run.record_every=1", "run.duration=1"});
  world.robots.placement = {{10, 10, 0}, {13, 10, 0}, {80, 80, 0}, {120, 40, 0}, {40, 120, 0}};
  const PlacementSample sample = sample_placements(world, 1);
  ASSERT_EQ(sample.partitions.size(), 1u);
  EXPECT_EQ(sample.partitions.begin()->first, (Partition{2, 1, 1, 1}));
  const std::vector<VariantPrediction> predictions = predict(world, nullptr, &sample);
  ASSERT_FALSE(predictions.empty());
  for (const VariantPrediction& prediction : predictions) {
    double at_one = -1.0;
    for (const TidyValue& value : prediction.extra) {
      if (value.quantity == "partition:2+1+1+1" && value.step == 1) at_one = value.value;
    }
    EXPECT_GT(at_one, 0.999) << prediction.variant;
  }
}

}  // namespace
}  // namespace swarmagg
