// `swarmagg view WORLD`: the live view (src/view/): runs one replicate of the world in a
// window, steps and inspects it; --script drives it from a file of commands.
#include "view/view_command.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/world_options.hpp"
#include "core/errors.hpp"
#include "render/render_size.hpp"
#include "view/view_session.hpp"
#include "view/view_window.hpp"

namespace swarmagg::cli {
namespace {

struct ViewCommandOptions {
  WorldOptions world;
  int replicate = 0;
  std::string script;
  std::optional<std::string> size;
  std::int64_t frames = 0;
};

int view_command(const ViewCommandOptions& options) {
  // Before anything slow: without a display, say so at once.
  if (const std::string problem = display_problem(); !problem.empty()) throw InputError(problem);
  const WorldSpec spec = options.world.load();
  ViewWindowOptions window;
  window.width = spec.render.width;
  window.height = spec.render.height;
  if (options.size) {
    const RenderSize size = parse_render_size(*options.size);
    window.width = size.width;
    window.height = size.height;
  }
  if (!options.script.empty()) window.script = read_view_script(options.script);
  if (options.frames < 0)
    throw InputError("--frames " + std::to_string(options.frames) + ": expected >= 0");
  window.frames = options.frames;
  ViewSession session(spec, options.replicate, std::cout);
  run_view_window(session, window);
  return 0;
}

}  // namespace

void add_view_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<ViewCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "view", "Watch, step and inspect one replicate of a world live in a window (docs/view.md)");
  options->world.add_to(*command, false);
  command->add_option("--engine", options->world.engine,
                      "Engine: kinematic or box2d (engine.type)");
  command->add_option("--seed", options->world.seed, "World seed (run.seed)")->type_name("UINT");
  command->add_option("--replicate", options->replicate,
                      "Which replicate to run (its generator is the one `run` gives it)");
  command->add_option(
      "--script", options->script,
      "Commands to run, one a line (step N, play, pause, speed K, select ID, "
      "colour ..., overlay NAME on|off, panel on|off, record on|off, screenshot PATH, hash, "
      "quit; docs/view.md)");
  command->add_option("--size", options->size, "Window size WxH (default render.width x height)");
  command->add_option("--frames", options->frames,
                      "Quit after N frames and print the frame rate (0: run until closed)");
  command->callback([options, &action] { action = [options] { return view_command(*options); }; });
}

}  // namespace swarmagg::cli
