#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/merge_removals.hpp"
#include "core/counted.hpp"
#include "output/output_check.hpp"
#include "run/interrupt.hpp"
#include "sweep/sweep_merge.hpp"

namespace swarmagg::cli {
namespace {

struct MergeCommandOptions {
  std::vector<std::string> folders;
  std::string out;
  bool quiet = false;
  bool force = false;
};

int merge_command(const MergeCommandOptions& command) {
  const std::vector<std::filesystem::path> folders(command.folders.begin(), command.folders.end());
  check_output_folder(command.out, "--out");
  install_interrupt_handlers();
  const MergeReport report = merge_sweep(folders, command.out, command.force);
  if (!command.quiet) {
    std::cout << "merged " << counted(report.runs, "run") << " ("
              << counted(report.points, "parameter point") << ") into " << command.out << "/:";
    for (const std::filesystem::path& file : report.files)
      std::cout << " " << file.filename().string();
    std::cout << "\n";
    std::cout << merge_removals_text(report, command.out, false);
  }
  return 0;
}

}  // namespace

void add_merge_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<MergeCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "merge", "Combine the output folders of a sweep's shards into tidy CSVs and summaries");
  command->add_option("folders", options->folders, "Sweep output folders (the shards' --out)")
      ->required();
  command->add_option("--out", options->out, "Folder for the merged outputs")->required();
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  command->add_flag("--force", options->force,
                    "Merge into a folder that holds another sweep's merge or a run "
                    "(refused otherwise)");
  command->callback([options, &action] { action = [options] { return merge_command(*options); }; });
}

}  // namespace swarmagg::cli
