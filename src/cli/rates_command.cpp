// `swarmagg rates WORLD.yaml [--engine] [--replicates N] [--seed S] [--threads T] [--set ...]
// [--out DIR]`: runs the world and measures every model term as events over exposure
// (docs/models.md): rates.csv, rates.json and a plot per term.
#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/progress_option.hpp"
#include "cli/world_options.hpp"
#include "core/counted.hpp"
#include "models/predictions.hpp"
#include "output/output_check.hpp"
#include "rates/rate_outputs.hpp"
#include "rates/rates_text.hpp"
#include "run/earlier_run.hpp"
#include "run/interrupt.hpp"
#include "run/measured_run.hpp"
#include "run/placement_sample.hpp"
#include "run/run_folder.hpp"

namespace swarmagg::cli {
namespace {

struct RatesCommandOptions {
  WorldOptions world;
  std::string out;
  bool quiet = false;
  bool force = false;
  ProgressOption progress;
};

int rates_command(const RatesCommandOptions& options) {
  const WorldSpec spec = options.world.load();
  const std::filesystem::path out =
      options.out.empty() ? default_run_folder(spec) : std::filesystem::path(options.out);
  check_output_folder(out, options.out.empty() ? "the run folder" : "--out");
  refuse_another_worlds_outputs(out, spec, "rates", options.force);
  install_interrupt_handlers();
  RunOptions run_options;
  run_options.progress = options.progress.shown(options.quiet);
  run_options.keep_rows = false;  // rates are tallied while the replicates run
  const MeasuredRun run = run_world_measuring(spec, run_options, true);
  std::string no_start;
  const std::optional<PlacementSample> start = placement_start_or_reason(spec, 0, no_start);
  if (!no_start.empty()) std::cerr << "note: " << second_order_initial_note(no_start) << "\n";
  const std::vector<RateRow> rows = measured_rate_rows(spec, *run.rates, start ? &*start : nullptr);
  std::vector<std::string> failures;
  clear_earlier_rates(out, failures);
  for (const std::string& failure : failures)
    std::cerr << "warning: cannot remove the earlier rates' " << failure << "\n";
  write_rate_outputs(spec, *run.rates, rows, out);
  if (options.quiet) return 0;
  for (const std::string& line : rate_summary_lines(rows)) std::cout << line << "\n";
  // The ratios to the models' rates compare with models that assume what this world may not.
  for (const std::string& caveat : world_caveats(spec)) std::cerr << "note: " << caveat << "\n";
  std::cout << spec.name << ": rates of " << counted(spec.run.replicates, "replicate") << " x "
            << spec.steps() << " steps in " << run.result.wall_seconds << " s; outputs in "
            << out.string() << "/\n";
  return 0;
}

}  // namespace

void add_rates_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<RatesCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "rates", "Measure every model term (encounter, growth rates) of a world by simulation");
  options->world.add_to(*command);
  command->add_option(
      "--out", options->out,
      "Output folder for rates.csv, rates.json and plots (default runs/<world name>)");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  command->add_flag(
      "--force", options->force,
      "Write into a folder that holds a run or rates of another world (refused otherwise)");
  options->progress.add_to(*command);
  command->callback([options, &action] { action = [options] { return rates_command(*options); }; });
}

}  // namespace swarmagg::cli
