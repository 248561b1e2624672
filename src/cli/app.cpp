#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <optional>

#include "cli/commands.hpp"
#include "cli/decimal_integer.hpp"
#include "config/did_you_mean.hpp"
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

// Ctrl-C reaches gnuplot and ffmpeg too: their failure is the interruption's, also when it
// reads as bad input (ffmpeg's probe of what it can make, stopped by the signal, looks like an
// ffmpeg that cannot make that kind of video).
int failed(const std::string& prefix, const std::string& message, int code) {
  if (const int signal_number = interrupt_signal()) return interrupted(signal_number);
  std::cerr << prefix << message << "\n";
  return code;
}

// CLI11 would call a misspelt command "a subcommand is required" (it takes the word for a
// stray argument): name the word and the nearest command instead.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  std::vector<std::string> commands;
  for (const CLI::App* command : app.get_subcommands({})) commands.push_back(command->get_name());
  const std::string word = argv[1];
  if (std::find(commands.begin(), commands.end(), word) != commands.end()) return std::nullopt;
  std::string message = "swarmagg: unknown command '" + word + "'";
  if (const auto nearest = closest_name(word, commands))
    message += "; did you mean '" + *nearest + "'?";
  return message + " (swarmagg --help lists the commands)";
}

// CLI11's own refusals ("world is required") as the others read: prefixed with the command
// that refused, and pointing at that command's help rather than the program's.
std::string parse_failure_message(const CLI::App* app, const CLI::Error& error) {
  std::string command = "swarmagg";
  for (const CLI::App* sub : app->get_subcommands()) command += " " + sub->get_name();
  return command + ": " + error.what() + " (" + command + " --help lists the options)\n";
}

// An empty path would silently mean the default (`--out ""`: the default folder) or nothing
// at all (`--video ""`: no video): refused, as a missing value is.
void refuse_empty_paths(CLI::App& app) {
  const CLI::Validator non_empty(
      [](std::string& value) { return value.empty() ? "expected a path, got ''" : ""; }, "");
  for (CLI::App* command : app.get_subcommands({})) {
    for (const char* name : {"--out", "--video", "--render-dir", "--rates", "--script"}) {
      CLI::Option* option = command->get_option_no_throw(name);
      if (option != nullptr && option->get_type_size() != 0)
        option->check(non_empty);  // flags: none
    }
  }
}

// What was printed must have reached its reader: a full disk or a closed pipe behind `>`
// otherwise ends a command such as `validate` or `keys` with success and an empty file.
// Returns why it did not (a guess when the failing write was an earlier one, whose errno is
// gone), or nothing when every write succeeded.
std::optional<std::string> standard_output_failure() {
  const bool failed_earlier = std::cout.fail() || std::ferror(stdout);
  std::cout.flush();
  errno = 0;
  if (std::fflush(stdout) != 0 && errno != 0) return std::string(": ") + std::strerror(errno);
  if (failed_earlier || std::cout.fail() || std::ferror(stdout))
    return std::string(" (a full disk, or a reader that went away?)");
  return std::nullopt;
}

// `code`, or 1 with a message when standard output did not reach its reader.
int standard_output_checked(int code) {
  if (const auto failure = standard_output_failure()) {
    std::cerr << "swarmagg: error: cannot write to standard output" << *failure << "\n";
    return 1;
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  h5::skip_hdf5_exit_cleanup();
  // Named here, not from argv[0], so the help reads the same however swarmagg was started.
  CLI::App app{"swarmagg: self-organized aggregation in 2D robot swarms", "swarmagg"};
  app.require_subcommand(1);
  app.set_version_flag("--version", SWARMAGG_VERSION);
  app.failure_message(parse_failure_message);  // before the commands, which inherit it
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
  refuse_empty_paths(app);
  read_integers_in_decimal(app);
  if (const auto message = unknown_command(app, argc, argv)) {
    std::cerr << *message << "\n";
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // --help and --version print to standard output
    if (code == 0) return standard_output_checked(0);
    return 2;
  }
  try {
    const int code = action ? action() : 0;
    // A signal that came during work that does not look for one (gnuplot, the last writes)
    // still ends the command as interrupted, not as a success.
    throw_if_interrupted();
    return standard_output_checked(code);
  } catch (const Interrupted& e) {
    return interrupted(e.signal_number());
  } catch (const InputError& e) {
    return failed("swarmagg: ", e.what(), 2);
  } catch (const std::bad_alloc&) {
    std::cerr << "swarmagg: error: out of memory: the world (agents, replicates run at once) or "
                 "the sweep needs more memory than this machine gives; use fewer agents, fewer "
                 "--threads or a smaller sweep\n";
    return 1;
  } catch (const std::exception& e) {
    return failed("swarmagg: error: ", e.what(), 1);
  }
}

}  // namespace swarmagg::cli
