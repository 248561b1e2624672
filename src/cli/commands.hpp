#pragma once
// Every subcommand lives in its own file and adds itself to the application with one of
// these functions. The action it stores runs after a successful parse and returns the exit
// code (0 success, 2 bad input, 1 failure); exceptions are mapped in app.cpp.
#include <functional>

namespace CLI {
class App;
}  // namespace CLI

namespace swarmagg::cli {

using Action = std::function<int()>;

// --quiet keeps warnings and the notes that say an output was left out and why (no model.csv
// for a world the models cannot describe, plots without gnuplot): a script would miss them.
inline constexpr const char* kQuietHelp =
    "Print nothing but errors, warnings and notes on outputs left out";

void add_run_command(CLI::App& app, Action& action);
void add_render_command(CLI::App& app, Action& action);
void add_view_command(CLI::App& app, Action& action);
void add_video_command(CLI::App& app, Action& action);
void add_model_command(CLI::App& app, Action& action);
void add_rates_command(CLI::App& app, Action& action);
void add_validate_command(CLI::App& app, Action& action);
void add_bench_command(CLI::App& app, Action& action);
void add_sweep_command(CLI::App& app, Action& action);
void add_merge_command(CLI::App& app, Action& action);
void add_reproduce_command(CLI::App& app, Action& action);
void add_compare_command(CLI::App& app, Action& action);
void add_plot_command(CLI::App& app, Action& action);
void add_keys_command(CLI::App& app, Action& action);
void add_help_command(CLI::App& app, Action& action);

int main(int argc, char** argv);

}  // namespace swarmagg::cli
