// `swarmagg model WORLD.yaml [--out DIR]`: the world's macroscopic predictions (docs/models.md),
// written beside a run of the same world so that the two plot together.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <optional>
#include <sstream>

#include "analysis/model_errors.hpp"
#include "cli/commands.hpp"
#include "cli/follow_up_commands.hpp"
#include "cli/progress_option.hpp"
#include "cli/world_options.hpp"
#include "config/world_difference.hpp"
#include "config/world_loader.hpp"
#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "models/measured_rates.hpp"
#include "models/predictions.hpp"
#include "output/output_check.hpp"
#include "rates/rates_csv.hpp"
#include "rates/rates_origin.hpp"
#include "run/earlier_run.hpp"
#include "run/interrupt.hpp"
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
  ProgressOption progress;
  bool force = false;
};

// The terms of `rates_csv`, refused (InputError naming the file) when no run of `spec` could
// have measured them, with a warning for each reason to doubt they belong to it.
MeasuredTerms read_measured_terms(const std::string& rates_csv, const WorldSpec& spec) {
  const std::vector<RateRow> rows = read_rates_csv(rates_csv);
  // A header alone measured nothing: its `measured` variants would be the world's own, named
  // as measured.
  if (rows.empty()) {
    throw InputError(rates_csv +
                     ": holds a header but no rows; expected the terms a run measured (the "
                     "rates.csv of `swarmagg rates` or `run --rates`)");
  }
  MeasuredTerms terms = measured_terms(rows);
  try {
    check_measured_terms(spec, terms);
  } catch (const InputError& e) {
    throw InputError(rates_csv + ": " + e.what());
  }
  for (const std::string& doubt : rates_origin_doubts(rates_csv, rows, spec))
    std::cerr << "warning: " << rates_csv << ": " << doubt << "\n";
  return terms;
}

// Where a measured start begins, as placement_start_note says it for a sampled one.
std::string measured_start_note(const MeasuredTerms& terms, const std::string& rates_csv) {
  double noa = 0.0;
  for (const auto& [size, count] : terms.initial) noa += count;
  std::ostringstream text;
  text << "from step 1 the models start where the first decision leaves the swarm, " << noa
       << " aggregates: measured in " << rates_csv
       << " (model.initial_state: measured); at step 0, as in the runs, no agent waits";
  return text.str();
}

// Errors of an earlier model must not stay beside this one; a summary that cannot be
// rewritten has none to keep.
void remove_stale_model_errors(const std::filesystem::path& out) {
  try {
    remove_model_errors(out);
  } catch (const std::exception& e) {
    std::cerr << "warning: " << e.what() << "\n";
  }
}

// In a run's folder, summary.json's model errors describe the model beside the run: the one
// just written, not an earlier model's (which may list a variant this one has not), nor none
// (a run stopped before its model, or run with --no-model). A model of another run (its
// length, recorded steps or replicates differ: the errors and noise floors would compare
// unlike things) leaves none, and says so even under --quiet (errors left out). Returns what
// was done otherwise, for the user; a damaged run is a warning, since the model itself was
// written, and the earlier errors go with it when they can.
std::optional<std::string> update_run_model_errors(const std::filesystem::path& out,
                                                   const WorldSpec& spec) {
  if (!holds_complete_run(out)) return std::nullopt;
  try {
    const std::string resolved = resolved_world_in(out);
    const std::vector<std::string> differences = measured_run_differences(resolved, spec);
    if (differences.empty()) {
      write_model_errors(out);
      return "the run's summary.json has their errors; `swarmagg plot " + shell_word(out.string()) +
             "` redraws its plots with them";
    }
    remove_model_errors(out);
    const WorldSpec run = load_world_text(resolved, (out / "world.resolved.yaml").string());
    std::cerr << "note: the run in " << out.string() << "/ is another run ("
              << differences_text(differences) << "): its summary.json keeps no model_errors; `"
              << rates_and_model_commands(out, run.model.initial_state == InitialState::Measured)
              << "` gives them\n";
    return std::nullopt;
  } catch (const InputError& e) {
    std::cerr << "warning: the model is written, but not its errors in the run's summary.json: "
              << e.what() << "\n";
    remove_stale_model_errors(out);
    return std::nullopt;
  }
}

int model_command(const ModelCommandOptions& options) {
  const WorldSpec spec = options.world.load();
  const std::filesystem::path out =
      options.out.empty() ? default_run_folder(spec) : std::filesystem::path(options.out);
  check_output_folder(out, options.out.empty() ? "the run folder" : "--out");
  refuse_another_worlds_outputs(out, spec, "model", options.force);
  const auto start = std::chrono::steady_clock::now();
  std::optional<MeasuredTerms> measured;
  if (!options.rates.empty()) measured = read_measured_terms(options.rates, spec);
  check_predictable(spec);  // before the placements are drawn (seconds for a large swarm)
  // Ctrl-C then stops the placements or the variants' walks, and the folder keeps its outputs.
  install_interrupt_handlers();
  const std::optional<PlacementSample> sample = placement_start(spec, 0);
  const std::vector<VariantPrediction> predictions = write_model_outputs(
      spec, pending_predictions(spec, measured ? &*measured : nullptr, sample ? &*sample : nullptr),
      out, options.progress.shown(options.quiet));
  const std::optional<std::string> errors_note = update_run_model_errors(out, spec);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  if (options.quiet) return 0;
  for (const std::string& caveat : model_caveats(spec)) std::cerr << "note: " << caveat << "\n";
  if (const std::string note = no_model_note(spec); !note.empty())
    std::cerr << "note: " << note << "\n";
  if (measured) std::cerr << "note: " << measured_variant_note(spec, *measured) << "\n";
  if (sample) std::cerr << "note: " << placement_start_note(*sample) << "\n";
  if (measured && spec.model.initial_state == InitialState::Measured)
    std::cerr << "note: " << measured_start_note(*measured, options.rates) << "\n";
  for (const VariantPrediction& prediction : predictions) {
    std::cout << prediction_summary(prediction) << "\n";
  }
  std::cout << spec.name << ": " << predictions.size() << " model variants in " << elapsed.count()
            << " s; outputs in " << out.string() << "/\n";
  if (errors_note) std::cout << *errors_note << "\n";
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
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  options->progress.add_to(*command);
  command->add_flag(
      "--force", options->force,
      "Write into a folder that holds a run or rates of another world (refused otherwise)");
  command->callback([options, &action] { action = [options] { return model_command(*options); }; });
}

}  // namespace swarmagg::cli
