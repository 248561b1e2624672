#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "core/errors.hpp"
#include "output/hdf5_file.hpp"
#include "run/interrupt.hpp"
#include "swarmagg_version.hpp"

namespace swarmagg::cli {
namespace {

int interrupted(int signal_number) {
  std::cerr << "swarmagg: interrupted; completed outputs are intact\n";
  return Interrupted(signal_number).exit_code();
}

}  // namespace

int main(int argc, char** argv) {
  h5::skip_hdf5_exit_cleanup();
  // Named here, not from argv[0], so the help reads the same however swarmagg was started.
  CLI::App app{"swarmagg: self-organized aggregation in 2D robot swarms", "swarmagg"};
  app.require_subcommand(1);
  app.set_version_flag("--version", SWARMAGG_VERSION);
  Action action;
  // One line per subcommand (keep this list in the order of `swarmagg --help`).
  add_run_command(app, action);
  add_render_command(app, action);
  add_view_command(app, action);
  add_video_command(app, action);
  add_model_command(app, action);
  add_rates_command(app, action);
  add_sweep_command(app, action);
  add_merge_command(app, action);
  add_plot_command(app, action);
  add_reproduce_command(app, action);
  add_compare_command(app, action);
  add_validate_command(app, action);
  add_bench_command(app, action);
  add_keys_command(app, action);
  add_help_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    const int code = action ? action() : 0;
    // A signal that came during work that does not look for one (the models, gnuplot) still
    // ends the command as interrupted, not as a success.
    throw_if_interrupted();
    return code;
  } catch (const Interrupted& e) {
    return interrupted(e.signal_number());
  } catch (const InputError& e) {
    std::cerr << "swarmagg: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    // Ctrl-C reaches gnuplot and ffmpeg too: their failure is the interruption's.
    if (const int signal_number = interrupt_signal()) return interrupted(signal_number);
    std::cerr << "swarmagg: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace swarmagg::cli
