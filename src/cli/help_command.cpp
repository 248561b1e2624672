// `swarmagg help [COMMAND] [--markdown]`: one command's help, or every command's in one page.
// `--markdown` prints docs/reference/cli.md, which a test compares with this output, so the page
// cannot drift from the options the commands really take.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>

#include "cli/commands.hpp"
#include "core/errors.hpp"

namespace swarmagg::cli {
namespace {

void print_markdown(CLI::App& app) {
  std::cout
      << "# Command-line reference\n\n"
      << "<!-- Generated from the commands' own --help; do not edit by hand. -->\n"
      << "Regenerate this page after adding or changing a command or option:\n\n"
      << "```sh\nbuild/swarmagg help --markdown > docs/reference/cli.md\n```\n\n"
      << "(the test `docs_reference` fails while the page differs from that output).\n\n"
      << "Exit codes: 0 success; 2 bad input (the message names the file, line and key); 1"
         " failure; 130 or 143 interrupted by SIGINT or SIGTERM (completed outputs are intact,"
         " nothing half-written remains). Every command that takes a world also takes `--set"
         " key.path=value` (repeatable) with the keys of [world-keys.md](world-keys.md).\n\n"
      << "```text\n"
      << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal)
      << "```\n";
  for (CLI::App* command : app.get_subcommands({})) {
    std::cout << "\n## " << command->get_name() << "\n\n"
              << command->get_description() << ".\n\n"
              << "```text\n"
              << command->help(app.get_name()) << "```\n";
  }
}

}  // namespace

void add_help_command(CLI::App& app, Action& action) {
  auto markdown = std::make_shared<bool>(false);
  auto only = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "help", "Print the help of a command, or of every command (docs/reference/cli.md)");
  command->add_option("COMMAND", *only, "The command whose help to print (default: all)");
  command->add_flag("--markdown", *markdown,
                    "Print the page docs/reference/cli.md: every command's --help");
  command->callback([markdown, only, &app, &action] {
    action = [markdown, only, &app] {
      if (!only->empty() && *markdown) {
        throw InputError("help: --markdown prints every command's help; give no COMMAND with it");
      }
      if (!only->empty()) {
        const std::vector<CLI::App*> commands = app.get_subcommands({});
        const auto wanted = std::find_if(commands.begin(), commands.end(),
                                         [&](const CLI::App* c) { return c->get_name() == *only; });
        if (wanted == commands.end()) {
          throw InputError("help: unknown command '" + *only +
                           "' (swarmagg help lists every command's help)");
        }
        std::cout << (*wanted)->help(app.get_name());
      } else if (*markdown) {
        print_markdown(app);
      } else {
        for (CLI::App* sub : app.get_subcommands({})) {
          std::cout << sub->help(app.get_name()) << "\n";
        }
      }
      return 0;
    };
  });
}

}  // namespace swarmagg::cli
