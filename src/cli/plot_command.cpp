#include <CLI/CLI.hpp>
#include <iostream>

#include "analysis/run_files.hpp"
#include "cli/commands.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/output_check.hpp"
#include "plot/run_plots.hpp"
#include "plot/sweep_plots.hpp"
#include "run/interrupt.hpp"

namespace swarmagg::cli {
namespace {

struct PlotCommandOptions {
  std::string folder;
  std::string out;
  bool force = false;
  bool quiet = false;
};

// --out naming another run's or merged sweep's folder would replace its plots with these,
// which read as its own.
void refuse_anothers_plots(const std::filesystem::path& folder, const std::filesystem::path& out) {
  std::error_code error;
  if (std::filesystem::equivalent(folder, out, error)) return;
  for (const auto& [marker, what] :
       {std::pair{"world.resolved.yaml", "a run"}, std::pair{kSweepSummaryFile, "a merged sweep"},
        std::pair{"compare.json", "a comparison"}, std::pair{"sweep.json", "a sweep"}}) {
    if (!std::filesystem::exists(out / marker, error)) continue;
    throw InputError("--out " + out.string() + "/ holds " + what + " (" + marker +
                     "): its plots would be replaced by those of " + folder.string() +
                     "; pass --force to write there anyway, or --out DIR");
  }
}

// A comparison's or an unmerged sweep's folder holds no run of its own: says what to plot.
void refuse_folders_without_a_run(const std::filesystem::path& folder) {
  std::error_code error;
  if (std::filesystem::exists(folder / "world.resolved.yaml", error)) return;
  if (std::filesystem::exists(folder / "compare.json", error)) {
    throw InputError(folder.string() + ": a comparison's folder; its runs are " +
                     (folder / "kinematic").string() + " and " + (folder / "box2d").string() +
                     " (plot either), and compare drew noa.png and final.png itself");
  }
  if (std::filesystem::exists(folder / "sweep.json", error)) {
    throw InputError(folder.string() +
                     ": a sweep's folder not merged yet (no sweep_summary.csv); run `swarmagg "
                     "merge` on its shard folders (or let the sweep finish), then plot the merged "
                     "folder, or plot one run in its runs/");
  }
}

// A merged sweep folder (sweep_summary.csv) gets the sweep's plots; any other folder must
// hold a finished run.
int plot_command(const PlotCommandOptions& options) {
  const std::filesystem::path folder(options.folder);
  const std::filesystem::path out =
      options.out.empty() ? folder : std::filesystem::path(options.out);
  if (!options.out.empty()) {
    check_output_folder(out, "--out");
    if (!options.force) refuse_anothers_plots(folder, out);
  }
  // A killed plot's hidden scripts and PNGs (plot/staged_script.hpp) are garbage.
  for (const std::filesystem::path& drawn : {out, out / "plots"}) {
    if (std::filesystem::is_directory(drawn)) remove_stale_temporaries(drawn);
  }
  const bool sweep = std::filesystem::exists(folder / kSweepSummaryFile);
  if (!sweep) {
    refuse_folders_without_a_run(folder);
    // A stored run may have been cut short or edited since: it would be drawn as the run.
    check_holds_every_row(read_run_files(folder));
  }
  const PlotOutcome outcome = sweep ? draw_sweep_plots(folder, out) : draw_run_plots(folder, out);
  throw_if_interrupted();  // gnuplot's half-drawn plots are the interruption's
  for (const std::string& failure : outcome.failures) std::cerr << "swarmagg: " << failure << "\n";
  if (!options.quiet) {
    std::cout << "drew " << outcome.drawn.size() << " plot(s) into " << out.string() << "/:";
    for (const std::filesystem::path& png : outcome.drawn)
      std::cout << " " << png.filename().string();
    std::cout << " (scripts and CSVs in " << (out / kPlotsFolder).string() << "/)\n";
  }
  return outcome.failures.empty() ? 0 : 1;
}

}  // namespace

void add_plot_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<PlotCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "plot", "Redraw the plots of a finished run or merged sweep from its files (no simulation)");
  command
      ->add_option("folder", options->folder,
                   "A run folder (world.resolved.yaml, timeseries.csv, ...) or a merged sweep "
                   "folder (sweep_summary.csv)")
      ->required();
  command->add_option("--out", options->out,
                      "Where the PNGs go (scripts and CSVs in <out>/plots/; default: the folder)");
  command->add_flag("--force", options->force,
                    "Write into an --out folder that holds another run or merged sweep");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  command->callback([options, &action] { action = [options] { return plot_command(*options); }; });
}

}  // namespace swarmagg::cli
