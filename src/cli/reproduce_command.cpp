#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/paper_worlds.hpp"
#include "cli/progress_option.hpp"
#include "core/errors.hpp"
#include "output/output_check.hpp"
#include "reproduce/reproduce.hpp"
#include "run/interrupt.hpp"

namespace swarmagg::cli {
namespace {

struct ReproduceCommandOptions {
  ReproduceOptions reproduce;
  std::string out = "reproduce";
  std::string worlds;  // empty: paper_worlds_folder's default
  bool quiet = false;
  ProgressOption progress;
};

int reproduce_command(ReproduceCommandOptions options) {
  options.reproduce.out = options.out;
  options.reproduce.worlds = paper_worlds_folder(options.worlds);
  options.reproduce.progress = options.progress.shown(options.quiet);
  check_output_folder(options.reproduce.out, "--out");
  install_interrupt_handlers();
  std::ostream null_stream(nullptr);
  const ReproduceOutcome outcome =
      reproduce(options.reproduce, options.quiet ? null_stream : std::cout);
  if (!options.quiet) {
    std::cout << "report " << outcome.report.string() << ", plots in "
              << (options.reproduce.out / "plots").string() << "/ (" << outcome.wall_seconds
              << " s)\n";
  }
  return 0;
}

}  // namespace

void add_reproduce_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<ReproduceCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "reproduce",
      "Run every experiment of the paper, plot each figure with the models and check its claims");
  ReproduceOptions& r = options->reproduce;
  command->add_flag("--quick", r.quick, "Fewer replicates and shorter runs (same code path)");
  command->add_option("--out", options->out, "Output folder (default reproduce)");
  command
      ->add_option("--engine", r.engine, "Engine for every world: kinematic or box2d (engine.type)")
      ->check(CLI::IsMember({"kinematic", "box2d"}));
  command
      ->add_option("--threads", r.threads,
                   "Threads in all (0 = all cores): runs go side by side, one thread each, "
                   "as long as there are more runs than threads")
      ->check(CLI::Range(0, 1024));
  command->add_option("--only", r.only,
                      "Only the worlds whose name contains this text (repeatable); "
                      "timeout-series selects the leave-timeout series");
  command->add_option("--set", r.overrides,
                      "Override a key of every world, e.g. --set run.replicates=4");
  command
      ->add_option("--timeout-duration", r.timeout_duration,
                   "Run length in tu of the leave-timeout series (default: the paper worlds'; "
                   "--quick divides it by 25)")
      ->check(CLI::PositiveNumber);
  command->add_option("--worlds", options->worlds,
                      "Folder of the paper worlds (" + paper_worlds_default_help() + ")");
  // Checked before the runs, not by gnuplot after them: at least a pixel, at most what a
  // cairo surface holds.
  command->add_option("--plot-width", r.plot_size.width, "Plot width in pixels (default 900)")
      ->check(CLI::Range(1, 32767));
  command->add_option("--plot-height", r.plot_size.height, "Plot height in pixels (default 600)")
      ->check(CLI::Range(1, 32767));
  command->add_flag("--run-plots", r.run_plots,
                    "Also draw each run's rate plots (rates-<term>.png); without it their "
                    "gnuplot scripts and CSVs are written, and 'gnuplot rates-<term>.gp' in the "
                    "run folder draws one");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  options->progress.add_to(*command);
  command->callback(
      [options, &action] { action = [options] { return reproduce_command(*options); }; });
}

}  // namespace swarmagg::cli
