#include <iostream>

#include "cli/commands.hpp"
#include "cli/world_options.hpp"
#include "run/interrupt.hpp"
#include "run/run_folder.hpp"
#include "run/world_runner.hpp"

namespace swarmagg::cli {
namespace {

struct RunCommandOptions {
  WorldOptions world;
  std::string out;
  bool quiet = false;
  bool check = false;
};

int run_command(const RunCommandOptions& options) {
  const WorldSpec spec = options.world.load();
  const std::filesystem::path out = 
      options.out.empty() ? default_run_folder(spec) : std::filesystem::path(options.out);
  install_interrupt_handlers();
  RunOptions run_options;
  run_options.progress = !options.quiet;
  run_options.check = options.check;
  const RunResult result = run_world(spec, run_options);
  write_run_folder(spec, result, out);
  if (!options.quiet) {
    double noa = 0.0;
    for (const ReplicateOutcome& r : result.replicates) noa += r.rows.back().noa;
    std::cout << spec.name << ": " << spec.run.replicates << " replicates x " << spec.steps()
              << " steps in " << result.wall_seconds << " s on " << result.threads
              << " threads; mean final NOA " << noa / spec.run.replicates << "\n"
              << "outputs in " << out.string() << "/\n";
  }
  return 0;
}

}  // namespace

void add_run_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* command = app.add_subcommand("run", "Simulate a world's replicates and write outputs");
  options->world.add_to(*command);
  command->add_option("--out", options->out, "Output folder (default runs/<world name>)");
  command->add_flag("--quiet", options->quiet, "Print nothing but errors");
  command->add_flag("--check", options->check,
                    "Check invariants after every step (always on in Debug builds)");
  command->callback([options, &action] { action = [options] { return run_command(*options); }; });
}

}  // namespace swarmagg::cli
