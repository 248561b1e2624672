#include "cli/follow_up_commands.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace swarmagg::cli {

std::string shell_word(const std::string& text) {
  constexpr std::string_view kPlain = "_./-+=:,@";
  const std::string word = text.starts_with("-") ? "./" + text : text;
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [&](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || kPlain.find(c) != std::string_view::npos;
  });
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string rates_and_model_commands(const std::filesystem::path& folder, bool rates_needed,
                                     bool model) {
  const std::string out = shell_word(folder.string());
  const std::string world = shell_word((folder / "world.resolved.yaml").string());
  std::error_code error;
  const bool rates_there = std::filesystem::exists(folder / "rates.csv", error);
  std::string commands;
  if (rates_needed && !rates_there) commands = "swarmagg rates " + world + " --out " + out;
  if (!model) return commands;
  if (!commands.empty()) commands += " && ";
  commands += "swarmagg model " + world;
  if (rates_needed || rates_there)
    commands += " --rates " + shell_word((folder / "rates.csv").string());
  return commands + " --out " + out;
}

}  // namespace swarmagg::cli
