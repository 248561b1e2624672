// `swarmagg model WORLD.yaml [--out DIR]`: the world's macroscopic predictions (docs/models.md),
// written beside a run of the same world so that the two plot together.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <optional>

#include "cli/commands.hpp"
#include "cli/world_options.hpp"
#include "config/world_difference.hpp"
#include "core/errors.hpp"
#include "models/measured_rates.hpp"
#include "models/predictions.hpp"
#include "output/output_check.hpp"
#include "rates/rates_csv.hpp"
#include "rates/rates_origin.hpp"
#include "run/earlier_run.hpp"
#include "run/model_outputs.hpp"
#include "run/placement_sample.hpp"
#include "run/run_folder.hpp"

namespace swarmagg::cli {
namespace {

struct ModelCommandOptions {
  WorldOptions world;
  std::string out;
  std::string rates;
  bool quiet = false;
  bool force = false;
};

int model_command(const ModelCommandOptions& options) {
  const WorldSpec spec = options.world.load();
  const std::filesystem::path out =
      options.out.empty() ? default_run_folder(spec) : std::filesystem::path(options.out);
  check_output_folder(out, options.out.empty() ? "the run folder" : "--out");
  refuse_another_worlds_run(out, spec, "model", options.force);
  const auto start = std::chrono::steady_clock::now();
  std::optional<MeasuredTerms> measured;
  if (!options.rates.empty()) {
    measured = measured_terms(read_rates_csv(options.rates));
    try {
      check_measured_terms(spec, *measured);
    } catch (const InputError& e) {
      throw InputError(options.rates + ": " + e.what());
    }
    const std::vector<std::string> differences = rates_world_differences(options.rates, spec);
    if (!differences.empty()) {
      std::cerr << "warning: " << options.rates << " was measured in another world ("
                << differences_text(differences)
                << "): the measured variants feed its terms into this world's model\n";
    }
  }
  const std::optional<PlacementSample> sample = placement_start(spec, 0);
  const std::vector<VariantPrediction> predictions =
      predict(spec, measured ? &*measured : nullptr, sample ? &*sample : nullptr);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  write_model_outputs(spec, predictions, out);
  if (options.quiet) return 0;
  for (const std::string& caveat : model_caveats(spec)) std::cerr << "note: " << caveat << "\n";
  if (measured) std::cerr << "note: " << measured_variant_note(spec, *measured) << "\n";
  if (sample) std::cerr << "note: " << placement_start_note(*sample) << "\n";
  for (const VariantPrediction& prediction : predictions) {
    std::cout << prediction_summary(prediction) << "\n";
  }
  std::cout << spec.name << ": " << predictions.size() << " model variants in " << elapsed.count()
            << " s; outputs in " << out.string() << "/\n";
  return 0;
}

}  // namespace

void add_model_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<ModelCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "model", "Compute the world's macroscopic predictions (Bayindir or Soysal model)");
  options->world.add_to(*command, false);
  command->add_option(
      "--out", options->out,
      "Output folder for model.csv and model-timeseries/ (default runs/<world name>)");
  command->add_option("--rates", options->rates,
                      "Measured terms (rates.csv of `swarmagg rates` or `run --rates`): adds the "
                      "`measured` variants and the measured initial state");
  command->add_flag("--quiet", options->quiet, "Print nothing but errors");
  command->add_flag("--force", options->force,
                    "Write into a folder that holds a run of another world (refused otherwise)");
  command->callback([options, &action] { action = [options] { return model_command(*options); }; });
}

}  // namespace swarmagg::cli
