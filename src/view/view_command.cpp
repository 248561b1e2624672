#include "view/view_command.hpp"

#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.hpp"

namespace swarmagg {
namespace {

constexpr std::array<std::pair<Overlay, std::string_view>, 8> kOverlayNames{{
    {Overlay::Detection, "detection"},
    {Overlay::Approach, "approach"},
    {Overlay::Links, "links"},
    {Overlay::Neighbours, "neighbours"},
    {Overlay::Trails, "trails"},
    {Overlay::Ghosts, "ghosts"},
    {Overlay::Contacts, "contacts"},
    {Overlay::Tints, "tints"},
}};

std::vector<std::string> words_of(std::string_view line) {
  std::istringstream in{std::string(line)};
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw InputError(where + ": " + what);
}

std::int64_t integer(const std::string& text, std::int64_t low, std::int64_t high,
                     const std::string& where, const std::string& what) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < low || value > high) {
    fail(where, what + ": expected an integer from " + std::to_string(low) + " to " +
                    std::to_string(high) + ", got '" + text + "'");
  }
  return value;
}

bool on_off(const std::string& text, const std::string& where, const std::string& what) {
  if (text == "on") return true;
  if (text == "off") return false;
  fail(where, what + ": expected on or off, got '" + text + "'");
}

void expect_words(const std::vector<std::string>& words, std::size_t count,
                  const std::string& where, const std::string& usage) {
  if (words.size() != count) fail(where, "expected '" + usage + "'");
}

}  // namespace

std::string_view overlay_name(Overlay overlay) {
  for (const auto& [o, name] : kOverlayNames) {
    if (o == overlay) return name;
  }
  return "?";
}

bool parse_view_command(std::string_view line, const std::string& where, ViewCommand& out) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  const std::vector<std::string> words = words_of(line);
  if (words.empty()) return false;
  const std::string& verb = words[0];
  out = ViewCommand{};
  if (verb == "step") {
    expect_words(words, 2, where, "step N");
    out.action = ViewAction::Step;
    out.count = integer(words[1], 1, std::int64_t{1} << 40, where, "step");
  } else if (verb == "play" || verb == "pause" || verb == "hash" || verb == "quit") {
    expect_words(words, 1, where, verb);
    out.action = verb == "play"    ? ViewAction::Play
                 : verb == "pause" ? ViewAction::Pause
                 : verb == "hash"  ? ViewAction::Hash
                                   : ViewAction::Quit;
  } else if (verb == "speed") {
    expect_words(words, 2, where, "speed K");
    out.action = ViewAction::Speed;
    out.count = integer(words[1], 1, kMaxStepsPerFrame, where, "speed (steps per frame)");
  } else if (verb == "select") {
    expect_words(words, 2, where, "select ID");
    out.action = ViewAction::Select;
    out.count = words[1] == "none" ? -1 : integer(words[1], 0, INT32_MAX, where, "select");
  } else if (verb == "colour" || verb == "color") {
    expect_words(words, 2, where, "colour state|aggregate|size");
    out.action = ViewAction::Colour;
    if (words[1] == "state") {
      out.colour = ColourMode::State;
    } else if (words[1] == "aggregate") {
      out.colour = ColourMode::Aggregate;
    } else if (words[1] == "size") {
      out.colour = ColourMode::Size;
    } else {
      fail(where, "colour: expected state, aggregate or size, got '" + words[1] + "'");
    }
  } else if (verb == "overlay") {
    expect_words(words, 3, where, "overlay NAME on|off");
    out.action = ViewAction::Overlay;
    bool known = false;
    std::string names;
    for (const auto& [o, name] : kOverlayNames) {
      names += (names.empty() ? "" : ", ") + std::string(name);
      if (name == words[1]) {
        out.overlay = o;
        known = true;
      }
    }
    if (!known) fail(where, "overlay: expected one of " + names + ", got '" + words[1] + "'");
    out.on = on_off(words[2], where, "overlay " + words[1]);
  } else if (verb == "panel") {
    expect_words(words, 2, where, "panel on|off");
    out.action = ViewAction::Panel;
    out.on = on_off(words[1], where, "panel");
  } else if (verb == "record") {
    expect_words(words, 2, where, "record on|off");
    out.action = ViewAction::Record;
    out.on = on_off(words[1], where, "record");
  } else if (verb == "screenshot") {
    // The path is the rest of the line, so it may hold spaces.
    if (words.size() < 2) fail(where, "expected 'screenshot PATH'");
    out.action = ViewAction::Screenshot;
    const auto start = line.find_first_not_of(" \t", line.find(verb) + verb.size());
    const auto end = line.find_last_not_of(" \t\r");
    out.path = std::string(line.substr(start, end + 1 - start));
  } else {
    fail(where, "unknown command '" + verb +
                    "'; expected step, play, pause, speed, select, colour, overlay, panel, "
                    "record, screenshot, hash or quit");
  }
  return true;
}

std::vector<ViewCommand> read_view_script(const std::string& path) {
  // A folder opens as a stream that reads nothing: it would be an empty script.
  if (std::filesystem::is_directory(path))
    throw InputError(path + ": is a folder; expected a script of view commands");
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot read the script");
  std::vector<ViewCommand> commands;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    ViewCommand command;
    const std::string where = path + ":" + std::to_string(number);
    if (parse_view_command(line, where, command)) {
      command.origin = where;
      commands.push_back(std::move(command));
    }
  }
  if (in.bad()) throw InputError(path + ": cannot read the script");
  return commands;
}

}  // namespace swarmagg
