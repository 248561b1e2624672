// `swarmagg keys [--markdown]`: every world key of the key table with its type, what it
// accepts, its default and its meaning. `--markdown` prints docs/reference/world-keys.md,
// which a test compares with this output, so the page cannot drift from the table.
#include <yaml-cpp/yaml.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "config/world_keys.hpp"

namespace swarmagg::cli {
namespace {

// A key's default as a world file would spell it: written from a world that names nothing.
std::string default_text(const WorldKey& key) {
  YAML::Emitter out;
  out << YAML::Flow << key.write(WorldSpec{});
  return out.c_str();
}

// Text inside a code span of a Markdown table cell: only '|' would end the cell.
std::string code_cell(const std::string& text) {
  std::string cell;
  for (const char c : text) cell += c == '|' ? std::string("\\|") : std::string(1, c);
  return cell;
}

// Plain text in a Markdown table cell, where "<name>" would also read as an HTML tag.
std::string table_cell(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    escaped += c == '<' ? std::string("&lt;") : c == '>' ? std::string("&gt;") : std::string(1, c);
  }
  return code_cell(escaped);
}

std::string block_of(const std::string& path) {
  const auto dot = path.find('.');
  return dot == std::string::npos ? std::string("(top level)") : path.substr(0, dot);
}

void print_plain() {
  for (const WorldKey& key : world_keys()) {
    std::cout << key.path << "  (" << key.type << ", default " << default_text(key) << ")\n"
              << "    accepts: " << key.expected << "\n"
              << "    " << key.meaning << "\n";
  }
}

void print_markdown() {
  std::cout
      << "# World keys\n\n"
      << "<!-- Generated from the key table (src/config/world_keys.cpp and each controller's "
         "registration); do not edit by hand. -->\n"
      << "Regenerate this page after adding or changing a key:\n\n"
      << "```sh\nbuild/swarmagg keys --markdown > docs/reference/world-keys.md\n```\n\n"
      << "(the test `docs_reference` fails while the page differs from that output).\n\n"
      << "Every key a world file, `--set key.path=value`, `validate` and a sweep's `parameters`"
         " accept, by its dotted path. A world names only what differs from the defaults;"
         " `swarmagg validate WORLD.yaml` prints it with every default filled in. Lengths are"
         " in arena units (u), times in time units (tu); probabilities \"per step\" are per"
         " step of `engine.dt`. Keys marked with a controller's name apply to its worlds only."
         " What worlds are and how to write one: [worlds.md](../worlds.md).\n";
  std::string block;
  for (const WorldKey& key : world_keys()) {
    if (block_of(key.path) != block) {
      block = block_of(key.path);
      std::cout << "\n## " << block << "\n\n"
                << "| key | type | accepts | default | meaning |\n"
                << "|---|---|---|---|---|\n";
    }
    std::cout << "| `" << key.path << "` | " << key.type << " | " << table_cell(key.expected)
              << " | `" << code_cell(default_text(key)) << "` | " << table_cell(key.meaning)
              << " |\n";
  }
}

}  // namespace

void add_keys_command(CLI::App& app, Action& action) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand(
      "keys", "List every world key with its type, accepted values, default and meaning");
  command->add_flag("--markdown", *markdown,
                    "Print the page docs/reference/world-keys.md instead of plain text");
  command->callback([markdown, &action] {
    action = [markdown] {
      if (*markdown) {
        print_markdown();
      } else {
        print_plain();
      }
      return 0;
    };
  });
}

}  // namespace swarmagg::cli
