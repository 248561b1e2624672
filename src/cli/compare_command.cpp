#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/progress_option.hpp"
#include "cli/world_options.hpp"
#include "compare/compare_summary.hpp"
#include "compare/engine_comparison.hpp"
#include "config/world_override.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/made_folders.hpp"
#include "output/output_check.hpp"
#include "output/trajectory_layout.hpp"
#include "run/earlier_run.hpp"
#include "run/interrupt.hpp"

namespace swarmagg::cli {
namespace {

struct CompareCommandOptions {
  WorldOptions world;
  std::string out;
  bool force = false;
  bool quiet = false;
  ProgressOption progress;
};

int compare_command(const CompareCommandOptions& options) {
  // Each arm sets the engine itself; a --set of it would be recorded against the other arm.
  for (const WorldOverride& set : parse_overrides(options.world.overrides)) {
    if (set.key == "engine.type")
      throw InputError("--set engine.type: compare runs the world on both engines; leave it out");
  }
  const WorldSpec spec = options.world.load();
  // Welch's interval needs a spread on both sides.
  if (spec.run.replicates < 2)
    throw InputError("compare needs at least 2 replicates (--replicates)");
  const std::filesystem::path out =
      options.out.empty() ? default_compare_folder(spec) : std::filesystem::path(options.out);
  // A killed comparison leaves its rows' temporaries in `out`: garbage of a process that is
  // gone, not an earlier comparison to keep.
  remove_stale_temporaries(out);
  if (!options.force)
    refuse_to_replace(out, "an earlier comparison or run?", "the comparison or run in it");
  // The arms are compared, not watched: say so rather than leave the user looking for them.
  if (spec.run.trajectories > 0 || spec.render.every > 0) {
    std::cerr << "note: compare stores no trajectories and draws no frames (run.trajectories, "
                 "render.every); run each engine with `swarmagg run --engine` for those\n";
  }
  check_output_folder(out, options.out.empty() ? "the comparison folder" : "--out");
  install_interrupt_handlers();
  // The arms' rows are spooled into `out` while they run: a comparison that fails or is
  // interrupted removes them, and the folder if it was made for them.
  const MadeFolders made(out);
  const RemovedOnFailure made_only_for_this_comparison(made);
  const EngineComparison result = compare_engines(spec, options.progress.shown(options.quiet), out);
  // Only now: Ctrl-C before leaves the earlier comparison whole.
  // A run's folder given as --out loses its run too, as `run --force` would remove it.
  if (options.force) {
    std::vector<std::string> failures = remove_earlier_comparison(out);
    // A run's trajectories are its writer's to replace; a comparison writes none.
    std::error_code error;
    if (std::filesystem::is_regular_file(out / "world.resolved.yaml", error))
      remove_earlier_output(out / trajectory_layout::kFileName, failures);
    for (std::string& failure : clear_earlier_run(out)) failures.push_back(std::move(failure));
    for (const std::string& failure : failures)
      std::cerr << "warning: could not remove the earlier outputs' " << failure << "\n";
  }
  for (const std::string& failure : write_compare_folder(
           result.kinematic, result.box2d, result.stats, out, options.world.changes()))
    std::cerr << "warning: " << failure << "\n";
  if (!options.quiet) {
    std::cout << comparison_text(spec.name, result.stats) << "outputs in " << out.string() << "/\n";
  }
  return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<CompareCommandOptions>();
  CLI::App* command =
      app.add_subcommand("compare", "Run a world on the kinematic and Box2D engines and compare");
  options->world.add_to(*command, false);  // no --engine: compare runs both
  command->add_option("--replicates", options->world.replicates,
                      "Replicates per engine (run.replicates)");
  command->add_option("--seed", options->world.seed, "World seed (run.seed)")->type_name("UINT");
  command->add_option("--threads", options->world.threads, "Threads (run.threads; 0 = all cores)");
  command->add_option("--out", options->out, "Output folder (default runs/<world name>-compare)");
  command->add_flag(
      "--force", options->force,
      "Replace the comparison or run already in the output folder (other files stay)");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  options->progress.add_to(*command);
  command->callback(
      [options, &action] { action = [options] { return compare_command(*options); }; });
}

}  // namespace swarmagg::cli
