#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/merge_removals.hpp"
#include "cli/progress_option.hpp"
#include "core/counted.hpp"
#include "output/output_check.hpp"
#include "plot/run_plots.hpp"
#include "plot/sweep_plots.hpp"
#include "run/interrupt.hpp"
#include "sweep/shard.hpp"
#include "sweep/sweep_listing.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_merge.hpp"
#include "sweep/sweep_runner.hpp"

namespace swarmagg::cli {
namespace {

struct SweepCommandOptions {
  std::string sweep;
  std::string out;
  int threads = 0;
  std::string shard;
  bool list = false;
  bool force = false;
  bool quiet = false;
  ProgressOption progress;
  bool no_plots = false;
  bool run_plots = false;
};

void print_report(const SweepPlan& plan, const SweepOptions& options, const SweepReport& report) {
  std::cout << "sweep " << plan.name;
  if (!options.shard.whole()) std::cout << " (shard " << options.shard.text() << ")";
  std::cout << ": " << counted(report.selected, "run") << ", " << report.already_complete
            << " already complete, ran " << report.ran << " in " << report.wall_seconds << " s on "
            << counted(report.threads, "thread") << "\noutputs in " << options.out.string()
            << "/\n";
}

int sweep_command(const SweepCommandOptions& command) {
  const SweepPlan plan = load_sweep(command.sweep);
  SweepOptions options;
  options.out = command.out.empty() ? std::filesystem::path("runs") / plan.name
                                    : std::filesystem::path(command.out);
  options.threads = command.threads;
  options.replace_outdated = command.force;
  options.shard = command.shard.empty() ? Shard{} : parse_shard(command.shard);
  options.progress = command.progress.shown(command.quiet);
  if (command.list) {
    std::cout << sweep_listing(shard_runs(expand_sweep(plan), options.shard), options.out);
    return 0;
  }
  check_output_folder(options.out, command.out.empty() ? "the sweep folder" : "--out");
  // Checked once for the whole sweep, so a missing gnuplot is said once, not once a run.
  const std::string plots_missing = command.no_plots ? "" : plots_unavailable_reason();
  if (!plots_missing.empty()) std::cerr << "note: plots skipped: " << plots_missing << "\n";
  const bool sweep_plots = !command.no_plots && plots_missing.empty();
  // Each run's own plots cost more than a short run itself: drawn only when asked.
  options.plots = sweep_plots && command.run_plots;
  install_interrupt_handlers();
  const SweepReport report = run_sweep(plan, options);
  if (!command.quiet) print_report(plan, options, report);
  if (!options.shard.whole()) {
    if (!command.quiet) {
      std::cout
          << "when every shard is done: swarmagg merge <the shards' --out folders> --out DIR\n";
    }
    return 0;
  }
  // An unsharded sweep holds every run, so it merges itself.
  command.progress.phase(command.quiet, plan.name, "merging the runs");
  const MergeReport merged = merge_sweep({options.out}, options.out);
  if (!command.quiet) {
    std::cout << "merged " << counted(merged.runs, "run") << " into " << options.out.string()
              << "/\n"
              << merge_removals_text(merged, options.out.string(), sweep_plots);
  }
  if (!sweep_plots) return 0;
  command.progress.phase(command.quiet, plan.name, "drawing the sweep's plots (gnuplot)");
  const PlotOutcome plots = draw_sweep_plots(options.out, options.out);
  for (const std::string& failure : plots.failures) std::cerr << "warning: " << failure << "\n";
  if (!command.quiet) {
    std::cout << "plots:";
    for (const auto& png : plots.drawn) std::cout << " " << png.filename().string();
    std::cout << "\n";
  }
  return 0;
}

}  // namespace

void add_sweep_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<SweepCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "sweep", "Run a parameter sweep (grid x replicates); resumable, shardable for job arrays");
  command
      ->add_option("sweep", options->sweep, "Sweep file (YAML: base, parameters, replicates, seed)")
      ->required();
  command->add_option("--out", options->out, "Output folder (default runs/<sweep name>)");
  command->add_option("--threads", options->threads, "Runs in parallel (0 = all cores)")
      ->check(CLI::Range(0, 1024));  // as run.threads
  command->add_option("--shard", options->shard,
                      "Run only shard i of n (runs whose index mod n is i-1), e.g. 2/8");
  command->add_flag("--list", options->list, "Print the runs (index, seed, status) and exit");
  command->add_flag("--force", options->force,
                    "Replace runs whose folders hold results of another world (the sweep changed)");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  options->progress.add_to(*command);
  command->add_flag("--no-plots", options->no_plots, "Skip the merged sweep's plots (gnuplot)");
  command->add_flag("--run-plots", options->run_plots,
                    "Also draw each run's own plots in its folder (noa.png, states.png, ...)");
  command->callback([options, &action] { action = [options] { return sweep_command(*options); }; });
}

}  // namespace swarmagg::cli
