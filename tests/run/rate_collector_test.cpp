#include "run/rate_collector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "config/world_loader.hpp"
#include "models/aggregate_shape.hpp"
#include "models/initial_state.hpp"
#include "models/predictions.hpp"
#include "models/sample_statistics.hpp"
#include "observers/aggregate_geometry.hpp"
#include "observers/observer_scene.hpp"
#include "rates/geometry_fits.hpp"
#include "rates/rate_recorder.hpp"
#include "rates/rate_rows.hpp"
#include "run/replicate.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {
namespace {

WorldSpec paper_world(const std::string& file, const std::vector<std::string>& overrides) {
  return load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/paper/" + file, overrides);
}

RateTally measure(const WorldSpec& spec, RunResult* result = nullptr) {
  RateCollector collector(spec);
  RunOptions options;
  options.observers = [&collector](int index) { return collector.observer(index); };
  const RunResult run = run_world(spec, options);
  if (result) *result = run;
  return collector.total();
}

TEST(RateCollector, GhostEncountersPerPairMatchKineticTheory) {
  const WorldSpec spec = paper_world("collision-speed-1.yaml",
                                     {"run.duration=2500", "run.replicates=2", "run.threads=2"});
  const RateTally tally = measure(spec);
  const std::vector<RateRow> rows = measured_rate_rows(spec, tally);
  ASSERT_EQ(rows.front().term, "creation");
  const RateEstimate& e = rows.front().estimate;
  ASSERT_TRUE(e.rate);
  const double model = 8.0 * 4.0 * 1.0 / (std::numbers::pi * spec.arena.area());
  const double expected_events = model * e.exposure;
  ASSERT_GT(expected_events, 1000.0);
  // Poisson: the count is within 4 sd of its mean (sd = sqrt(mean)) but for 6e-5 of runs;
  // pairs already within s (a fraction pi s^2 / A = 3.5e-4) cannot newly meet.
  EXPECT_NEAR(static_cast<double>(e.events), expected_events, 4.0 * std::sqrt(expected_events));
  // The model value of the collision variant is the same kinetic rate.
  EXPECT_NEAR(rows.front().models.at(1).rate, model, 1e-15);
}

TEST(RateCollector, LeaveAttemptsPerMemberStepEqualP) {
  const WorldSpec spec =
      paper_world("full-0.0025.yaml", {"run.duration=1500", "run.replicates=2", "run.threads=2"});
  const RateTally tally = measure(spec);
  // Every member of a size-m aggregate tries with probability p per step: expected attempts
  // p * sum_m m * (aggregate steps of size m).
  double expected = 0.0, attempts = 0.0;
  for (int m = 2; m <= tally.agents; ++m) {
    const auto index = static_cast<std::size_t>(m);
    expected +=
        spec.controller.p_leave * m * static_cast<double>(tally.leave_aggregate_steps[index]);
    attempts += static_cast<double>(tally.attempts[index]);
  }
  ASSERT_GT(expected, 500.0);
  EXPECT_NEAR(attempts, expected, 4.0 * std::sqrt(expected));
  // And per size, each row's model value is m p / dt.
  for (const RateRow& row : measured_rate_rows(spec, tally)) {
    if (row.term != "attempt") continue;
    EXPECT_DOUBLE_EQ(row.models.front().rate, *row.size * spec.controller.p_leave / spec.engine.dt);
  }
}

// The pairs the first decision forms, over many seeded placements, against the derivation.
struct FirstDecisionSample {
  std::vector<double> pairs, triples;
};

FirstDecisionSample first_decisions(const WorldSpec& spec, int placements) {
  FirstDecisionSample sample;
  for (int index = 0; index < placements; ++index) {
    Replicate replicate(spec, index);
    replicate.step();
    double pairs = 0.0, triples = 0.0;
    for (const std::int32_t size : replicate.aggregates().sizes()) {
      pairs += size == 2;
      triples += size == 3;
    }
    sample.pairs.push_back(pairs);
    sample.triples.push_back(triples);
  }
  return sample;
}

double standard_error(const std::vector<double>& values) {
  return sample_sd(values) / std::sqrt(static_cast<double>(values.size()));
}

TEST(RateCollector, ExpectedPlacementPairsMatchTheMeanOverSeededPlacements) {
  // The 400 agents on 460 x 460 (creation rules), and the same with joining.
  for (const bool join : {false, true}) {
    WorldSpec spec = paper_world("creation-150.yaml",
                                 {"robots.count=400", "arena.width=460", "arena.height=460"});
    spec.controller.join = join;
    const FirstDecisionSample sample = first_decisions(spec, 1500);
    const FirstDecision expected = expected_first_decision(spec);
    const double se = standard_error(sample.pairs);
    EXPECT_NEAR(sample_mean(sample.pairs), expected.pairs, 3.0 * se) << "join " << join;
    if (!join) {
      // The first-order count (all close pairs, body exclusion included) is measurably off.
      const double first_order = 400.0 * 399.0 / 2.0 * placement_pair_probability(spec);
      EXPECT_GT(std::abs(sample_mean(sample.pairs) - first_order), 3.0 * se);
    }
  }
}

TEST(RateCollector, ExpectedPlacementTriplesMatchTheMeanOverSeededPlacements) {
  // Triples are second order, and four-agent clusters (third order, which the expansion
  // leaves out) take from them: at 400 agents on 460 x 460 that is ~0.08 of 0.64, so the
  // check runs where the third order is far below the standard error (200 agents).
  WorldSpec spec = paper_world("creation-growing-80.yaml",
                               {"robots.count=200", "arena.width=460", "arena.height=460"});
  const FirstDecisionSample sample = first_decisions(spec, 3000);
  const FirstDecision expected = expected_first_decision(spec);
  EXPECT_NEAR(sample_mean(sample.triples), expected.triples, 3.0 * standard_error(sample.triples));
  EXPECT_NEAR(sample_mean(sample.pairs), expected.pairs, 3.0 * standard_error(sample.pairs));
}

// Mean NOA over replicates at each recorded step.
std::vector<double> mean_noa(const RunResult& result) {
  std::vector<double> mean(result.replicates.front().rows.size(), 0.0);
  for (const ReplicateOutcome& r : result.replicates) {
    for (std::size_t i = 0; i < mean.size(); ++i) mean[i] += r.rows[i].noa;
  }
  for (double& m : mean) m /= static_cast<double>(result.replicates.size());
  return mean;
}

TEST(RateCollector, MeasuredVariantReproducesACreationOnlyWorld) {
  const WorldSpec spec =
      paper_world("creation-150.yaml", {"run.duration=600", "run.replicates=10", "run.threads=2",
                                        "model.stochastic_replicates=0", "run.record_every=50"});
  RunResult result;
  const RateTally tally = measure(spec, &result);
  const MeasuredTerms terms = measured_terms(measured_rate_rows(spec, tally));
  WorldSpec measured_start = spec;
  measured_start.model.initial_state = InitialState::Measured;
  const std::vector<VariantPrediction> predictions = predict(measured_start, &terms);
  const VariantPrediction& measured = predictions.back();
  ASSERT_EQ(measured.variant, "measured");
  const std::vector<double> simulated = mean_noa(result);
  ASSERT_EQ(simulated.size(), measured.series.size());
  for (std::size_t i = 0; i < simulated.size(); ++i) {
    if (result.replicates.front().rows[i].step < spec.steps() / 10) continue;
    EXPECT_NEAR(*measured.series[i].noa, simulated[i], 0.03 * simulated[i])
        << "step " << measured.series[i].step;
  }
}

// Hand-built hexagonal packs at spacing 2r (r = 1) measured as the collector measures them
// and fed through the recorder: the radius and rim rows hold R1 = 2 rings + r (the corners
// of the outer ring) and the outer ring's 6 rings members, with no spread between replicates.
TEST(RateCollector, HexagonalPacksGiveTheirRadiusAndRimRows) {
  WorldSpec spec = paper_world("full-0.0025.yaml", {"robots.count=40"});
  const ShapeRules rules = ShapeRules::for_world(spec);
  ASSERT_DOUBLE_EQ(rules.rim.reach, 2.4);
  RateTally tally(40);
  for (int replicate = 0; replicate < 2; ++replicate) {
    RateRecorder recorder(40, 100);
    for (const int rings : {1, 2, 3}) {
      testing::Scene scene;
      scene.add_hexagon(50.0, 50.0, rings, 2.0);
      std::vector<AgentId> members(scene.positions.size());
      for (std::size_t i = 0; i < members.size(); ++i) members[i] = static_cast<AgentId>(i);
      const AggregateShape shape =
          measure_aggregate(members, scene.positions, {scene.arena, 1.0, rules.rim});
      for (int observation = 0; observation < 5; ++observation)
        recorder.observe_shape(shape.size, shape.outer_radius, shape.rim);
    }
    tally.merge(recorder.finish());
  }
  const std::map<int, std::pair<double, double>> expected{
      {7, {3.0, 6.0}}, {19, {5.0, 12.0}}, {37, {7.0, 18.0}}};
  int checked = 0;
  for (const RateRow& row : measured_rate_rows(spec, tally)) {
    if (row.term != "radius" && row.term != "rim") continue;
    ASSERT_TRUE(expected.contains(*row.size)) << *row.size;
    const auto [radius, rim] = expected.at(*row.size);
    const double value = row.term == "radius" ? radius : rim;
    ASSERT_TRUE(row.estimate.rate) << row.term << " " << *row.size;
    EXPECT_EQ(row.estimate.events, 10u);
    EXPECT_NEAR(*row.estimate.rate, value, 1e-9) << row.term << " " << *row.size;
    // No spread; the interval's summed squares cancel to rounding (relative 1e-16, then a
    // square root).
    EXPECT_NEAR(*row.estimate.high - *row.estimate.low, 0.0, 1e-5);
    // Both Bayindir variants, with the paper's law on r_eff = s/4 = 1.
    ASSERT_EQ(row.models.size(), 2u);
    const double model = row.term == "radius" ? aggregate_radius(1.0, *row.size)
                                              : capped_periphery_agents(*row.size);
    EXPECT_DOUBLE_EQ(row.models.front().rate, model);
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

// A dense world with compaction: every aggregate observed at a recorded step after the
// first decision is one observation (their count is the NOA summed over those rows), an
// aggregate of at most 6 has no interior member (it would need 6 fellows), and a pair
// holds together within s, so its R1 lies between r + spacing / 2 and r + s / 2.
TEST(RateCollector, SamplesTheGeometryOfEveryAggregateAtTheRecordedSteps) {
  const WorldSpec spec =
      load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/compact.yaml",
                 {"robots.count=200", "run.duration=300", "run.replicates=2", "run.threads=2"});
  RunResult result;
  const RateTally tally = measure(spec, &result);
  std::uint64_t aggregates = 0;
  for (const ReplicateOutcome& r : result.replicates) {
    for (const TimeseriesRow& row : r.rows) aggregates += row.step >= 1 ? row.noa : 0;
  }
  std::uint64_t observations = 0;
  for (int m = 2; m <= tally.agents; ++m) {
    observations += tally.outer_radius[m].observations();
    EXPECT_EQ(tally.rim[m].observations(), tally.outer_radius[m].observations());
  }
  EXPECT_GT(aggregates, 100u);
  EXPECT_EQ(observations, aggregates);
  int small_sizes = 0;
  for (const RateRow& row : measured_rate_rows(spec, tally)) {
    if (!row.size || !row.estimate.rate) continue;
    if (row.term == "rim" && *row.size <= 6) {
      EXPECT_DOUBLE_EQ(*row.estimate.rate, *row.size);
      ++small_sizes;
    }
    if (row.term == "radius" && *row.size == 2) {
      EXPECT_GE(*row.estimate.rate, 2.0 - 0.05);
      EXPECT_LE(*row.estimate.rate, 3.0);
    }
  }
  EXPECT_GE(small_sizes, 3);
}

// `rates` clears earlier plots by kRateTerms: every term a run writes must be listed there.
TEST(RateCollector, EveryTermWrittenIsAKnownRateTerm) {
  for (const auto& [file, leave] :
       {std::pair<std::string, std::string>{"full-0.0025.yaml", "controller.p_leave=0.01"},
        {"soysal-5-constant.yaml", "controller.p0=0.01"}}) {
    const WorldSpec spec = paper_world(file, {"run.duration=400", "run.replicates=2", leave});
    const std::vector<RateRow> rows = measured_rate_rows(spec, measure(spec));
    std::set<std::string> terms;
    for (const RateRow& row : rows) terms.insert(row.term);
    EXPECT_GE(terms.size(), 6u) << file;
    for (const std::string& term : terms) {
      EXPECT_NE(std::find(std::begin(kRateTerms), std::end(kRateTerms), term), std::end(kRateTerms))
          << term << " in " << file;
    }
  }
}

}  // namespace
}  // namespace swarmagg
