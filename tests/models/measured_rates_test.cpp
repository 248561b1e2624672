#include "models/measured_rates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/errors.hpp"
#include "model_test_worlds.hpp"
#include "models/predictions.hpp"

namespace swarmagg {
namespace {

// What a run of a 60-agent world measures, roughly (dt = 0.1).
MeasuredTerms plausible_terms() {
  MeasuredTerms terms;
  terms.creation = 3e-4;
  terms.growth = {{2, 3e-3}, {3, 4e-3}};
  terms.attempt = {{2, 0.02}, {3, 0.03}};
  terms.returned = {{2, 0.4}};
  return terms;
}

TEST(MeasuredRates, PlausibleTermsPassAndEveryVariantStaysFinite) {
  WorldSpec world = testing::bayindir_world(60, 1e-3, true, true, 120.0);
  world.run.duration = 200.0;
  const MeasuredTerms terms = plausible_terms();
  EXPECT_NO_THROW(check_measured_terms(world, terms));
  for (const VariantPrediction& p : predict(world, &terms)) {
    for (const ModelRow& row : p.series) ASSERT_TRUE(!row.noa || std::isfinite(*row.noa));
  }
}

// Rates no run can measure drove the expected model to NaN NOA with exit 0.
TEST(MeasuredRates, RatesAboveOneEventPerStepAreRefusedByName) {
  WorldSpec world = testing::bayindir_world(60, 1e-3, true, true, 120.0);
  world.run.duration = 200.0;
  const auto refused = [&](MeasuredTerms terms, const std::string& what) {
    try {
      predict(world, &terms);
      ADD_FAILURE() << "accepted " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  MeasuredTerms terms = plausible_terms();
  terms.creation = 1e9;
  refused(terms, "measured creation rate 1e+09 per tu is more than one pair-up");
  terms = plausible_terms();
  terms.growth[3] = 11.0;  // 1.1 joins per searcher and aggregate per step of 0.1
  refused(terms, "measured growth 3 rate 11");
  terms = plausible_terms();
  terms.attempt[2] = 25.0;  // 2.5 attempts per step from a pair
  refused(terms, "measured attempt 2 rate 25 per tu is more LEAVE attempts than members");
  terms = plausible_terms();
  terms.attempt[2] = 19.0;  // 1.9 of its 2 members a step: possible
  EXPECT_NO_THROW(check_measured_terms(world, terms));
}

TEST(MeasuredRates, AMeasuredStartMustFitTheWorldsAgents) {
  WorldSpec world = testing::bayindir_world(60, 1e-3, true, true, 120.0);
  world.model.initial_state = InitialState::Measured;
  MeasuredTerms terms = plausible_terms();
  terms.initial = {{2, 3.6}, {3, 0.35}};
  EXPECT_NO_THROW(check_measured_terms(world, terms));
  const auto refused = [&](const std::map<int, double>& initial, const std::string& what) {
    MeasuredTerms start = terms;
    start.initial = initial;
    try {
      check_measured_terms(world, start);
      ADD_FAILURE() << "accepted " << what;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
    }
  };
  refused({{2, 3.6}, {61, 0.1}}, "aggregates of 61 agents in a world of 60");
  refused({{2, 31.0}}, "hold 62 agents on average, more than the world's 60");
  // Not the world's start: nothing to check.
  world.model.initial_state = InitialState::Placement;
  terms.initial = {{61, 1.0}};
  EXPECT_NO_THROW(check_measured_terms(world, terms));
}

TEST(MeasuredRates, SoysalTermsAreNamedAsItsRatesCsvNamesThem) {
  const WorldSpec world = testing::soysal_world(5, 150.0);
  MeasuredTerms terms;
  terms.creation = 10.01;
  try {
    check_measured_terms(world, terms);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("measured pairup rate 10.01"), std::string::npos)
        << e.what();
  }
}

// Possible per pair, 0.9 joins per searcher and aggregate in a step are still more joins
// than there are searchers once aggregates are many: the expected model overshoots.
TEST(MeasuredRates, AModelThatOvershootsTheAgentsIsRefusedNotWrittenAsNan) {
  WorldSpec world = testing::bayindir_world(60, 1e-3, true, true, 120.0);
  world.run.duration = 200.0;
  MeasuredTerms growing = plausible_terms();
  growing.growth = {{2, 9.0}, {3, 9.0}, {4, 9.0}};
  growing.returned.clear();  // else it would grow by its new joins (none measured)
  // 1.5 attempts per step from a pair, none returning: a pair loses more than it has, in a
  // step between two recorded ones (record_every 100), so the rows alone would not show it.
  MeasuredTerms leaving = plausible_terms();
  leaving.attempt[2] = 15.0;
  leaving.returned.clear();
  world.run.record_every = 100;
  for (const MeasuredTerms& terms : {growing, leaving}) {
    EXPECT_NO_THROW(check_measured_terms(world, terms));
    try {
      predict(world, &terms);
      ADD_FAILURE() << "wrote an overshooting model";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("the bayindir `measured` variant: the expected model "
                                           "left the range of the agents at step "),
                std::string::npos)
          << e.what();
    }
  }
}

// Once returns are taken out of the losses, a return is no join either: the chain grows by the
// new joins, and where those were too few to measure by the model's own join term, never by
// every join (returns included), which fed each return back as a join into any aggregate.
TEST(MeasuredRates, AReturnIsNeitherALossNorAJoin) {
  const WorldSpec world = testing::soysal_world(10, 150.0);
  const double dt = world.engine.dt;
  const SoysalRates model = soysal_rates(world, world.model.leaving);
  MeasuredTerms terms;
  terms.growth = {{4, 0.5}, {5, 0.6}};
  terms.new_growth = {{5, 0.02}};
  terms.attempt = {{5, 0.01}};
  terms.returned = {{5, 0.9}};
  const SoysalRates out = measured_soysal_rates(world, terms);
  EXPECT_DOUBLE_EQ(out.join[5], 0.02 * dt);
  EXPECT_DOUBLE_EQ(out.join[4], model.join[4]);
  EXPECT_NEAR(out.leave[5], 0.01 * dt * 0.1, 1e-15);
  // Without returns measured, every join is a join and every attempt a loss.
  terms.returned.clear();
  const SoysalRates all = measured_soysal_rates(world, terms);
  EXPECT_DOUBLE_EQ(all.join[4], 0.5 * dt);
  EXPECT_DOUBLE_EQ(all.join[5], 0.6 * dt);
  EXPECT_DOUBLE_EQ(all.leave[5], 0.01 * dt);
  WorldSpec bayindir = testing::bayindir_world(60, 1e-3, true, true, 120.0);
  terms.returned = {{5, 0.9}};
  const BayindirRates grown = measured_bayindir_rates(bayindir, terms);
  EXPECT_DOUBLE_EQ(grown.growth[4], bayindir_rates(bayindir, bayindir.model.creation).growth[4]);
  EXPECT_DOUBLE_EQ(grown.growth[5], 0.02 * bayindir.engine.dt);
}

}  // namespace
}  // namespace swarmagg
