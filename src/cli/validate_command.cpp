#include <CLI/CLI.hpp>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/world_options.hpp"
#include "config/world_writer.hpp"
#include "engine/engine.hpp"

namespace swarmagg::cli {

void add_validate_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<WorldOptions>();
  CLI::App* command =
      app.add_subcommand("validate", "Check a world file and print it fully resolved");
  options->add_to(*command);
  command->callback([options, &action] {
    action = [options] {
      const WorldSpec spec = options->load();
      check_engine_world(spec);  // what the engine refuses at its start (Box2D's limits)
      std::cout << world_to_yaml(spec);
      if (const std::string note = spec.rounded_duration_note(); !note.empty())
        std::cerr << "note: " << note << "\n";
      return 0;
    };
  });
}

}  // namespace swarmagg::cli
