// The model outputs are written while the variants are computed: what stays in memory is the
// last recorded step's rows of each variant (the summary line reads them), never the series,
// whose rows a long prediction could not hold (10^7 steps of the demo world took 11.6 GB).
#include "run/model_outputs.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "models/measured_rates.hpp"
#include "models/model_csv.hpp"
#include "models/model_test_worlds.hpp"
#include "models/predictions.hpp"
#include "output/scratch_folder.hpp"
#include "run/interrupt.hpp"

namespace swarmagg {
namespace {

// 20000 steps recorded every 10: 2001 recorded steps, each with 3 stochastic replicates.
WorldSpec long_world() {
  return load_world(
      std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml",
      {"robots.count=20", "run.duration=2000", "run.replicates=1", "model.stochastic_replicates=3",
       "model.initial_state=placement_second_order"});
}

constexpr std::size_t kRecordedSteps = 2001;
constexpr std::size_t kStochasticReplicates = 3;

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t lines_of(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

std::vector<std::string> names_below(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    names.push_back(std::filesystem::relative(entry.path(), folder).string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ModelOutputs, KeepOnlyEachVariantsLastStepWhileTheFilesHoldEveryRecordedStep) {
  const WorldSpec spec = long_world();
  const ScratchFolder out("model-outputs");
  const std::vector<VariantPrediction> written =
      write_model_outputs(spec, pending_predictions(spec), out.path());
  ASSERT_EQ(written.size(), 6u);  // original, collision, returns; each also stochastic
  for (const VariantPrediction& variant : written) {
    const std::size_t replicates = variant.stochastic ? kStochasticReplicates : 1;
    std::set<std::int64_t> steps_held;
    for (const ModelRow& row : variant.series) steps_held.insert(row.step);
    EXPECT_EQ(steps_held.size(), 1u)
        << variant.variant << " holds rows of other steps than its last";
    EXPECT_EQ(*steps_held.rbegin(), spec.steps()) << variant.variant;
    EXPECT_EQ(variant.series.size(), replicates) << variant.variant;
    const std::string file = variant.model + "-" + variant.variant + ".csv";
    EXPECT_EQ(lines_of(text_of(out.path() / "model-timeseries" / file)),
              1 + kRecordedSteps * replicates)
        << file;
  }
  EXPECT_FALSE(written[0].extra.empty());  // its size distribution and noise floor
  EXPECT_NE(prediction_summary(written[4]).find("mean +- sd of 3 replicates"), std::string::npos)
      << prediction_summary(written[4]);
}

// Written while computed or computed whole and then written: the same bytes.
TEST(ModelOutputs, AreTheTextsOfTheWholePredictions) {
  const WorldSpec spec = long_world();
  const ScratchFolder out("model-outputs");
  write_model_outputs(spec, pending_predictions(spec), out.path());
  const std::vector<VariantPrediction> whole = predict(spec);
  EXPECT_EQ(text_of(out.path() / "model.csv"), model_csv(whole, spec.engine.dt));
  for (const VariantPrediction& variant : whole) {
    const std::string file = variant.model + "-" + variant.variant + ".csv";
    EXPECT_EQ(text_of(out.path() / "model-timeseries" / file),
              model_timeseries_csv(variant, spec.engine.dt))
        << file;
  }
}

// Ctrl-C stops the computation; the earlier outputs stay whole and no temporary remains.
TEST(ModelOutputs, AnInterruptionLeavesTheEarlierOutputsAsTheyWere) {
  const WorldSpec spec = long_world();
  const ScratchFolder out("model-outputs");
  const ScratchFolder fresh("model-outputs");
  const std::filesystem::path made_for_it = fresh.path() / "new" / "run";
  write_model_outputs(spec, pending_predictions(spec), out.path());
  const std::vector<std::string> before = names_below(out.path());
  const std::string model_csv_before = text_of(out.path() / "model.csv");
  WorldSpec longer = spec;
  longer.run.duration = 4000.0;
  set_interrupt_signal(SIGINT);
  EXPECT_THROW(write_model_outputs(longer, pending_predictions(longer), out.path()), Interrupted);
  EXPECT_THROW(write_model_outputs(longer, pending_predictions(longer), made_for_it), Interrupted);
  set_interrupt_signal(0);
  EXPECT_EQ(names_below(out.path()), before);
  EXPECT_EQ(text_of(out.path() / "model.csv"), model_csv_before);
  EXPECT_EQ(names_below(fresh.path()), std::vector<std::string>{})
      << "left behind in a folder made for the outputs";
}

// A variant refused half-way through (measured terms that drive the expected model past the
// agents), after others were written: none of this model's files land.
TEST(ModelOutputs, AVariantRefusedMidWayLeavesTheEarlierOutputsAsTheyWere) {
  WorldSpec spec = testing::bayindir_world(60, 1e-3, true, true, 120.0);
  spec.run.duration = 200.0;
  const ScratchFolder out("model-outputs");
  write_model_outputs(spec, pending_predictions(spec), out.path());
  const std::vector<std::string> before = names_below(out.path());
  const std::string model_csv_before = text_of(out.path() / "model.csv");
  MeasuredTerms overshooting;
  overshooting.creation = 3e-4;
  overshooting.growth = {{2, 9.0}, {3, 9.0}, {4, 9.0}};
  overshooting.attempt = {{2, 0.02}, {3, 0.03}};
  spec.run.duration = 300.0;
  try {
    write_model_outputs(spec, pending_predictions(spec, &overshooting), out.path());
    ADD_FAILURE() << "wrote an overshooting model";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("left the range of the agents"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(names_below(out.path()), before);
  EXPECT_EQ(text_of(out.path() / "model.csv"), model_csv_before);
}

}  // namespace
}  // namespace swarmagg
