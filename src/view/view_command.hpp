#pragma once
// The commands that drive the live view, from a key press or from a line of a --script
// file; both go through one queue, so a script can reach every path of the view.
//   step N | play | pause | speed K | select ID | colour state|aggregate|size
//   overlay NAME on|off | panel on|off | record on|off | screenshot PATH | hash | quit
// plus what only keys send (reset, reseed, fit, zoom, ...).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/scene_options.hpp"

namespace swarmagg {

enum class ViewAction {
  Step,  // count steps, now
  Play,
  Pause,
  TogglePlay,
  Speed,       // count steps per frame (1 .. kMaxStepsPerFrame)
  Select,      // agent id, -1 for none
  Colour,      // colour mode
  Overlay,     // overlay on/off
  Panel,       // on/off
  Screenshot,  // path
  Hash,
  Quit,
  Reset,   // the same seed
  Reseed,  // the next seed
  Record,  // start or stop recording frames
  Fit,
};

// The overlays a script or a checkbox can switch, by their script names.
enum class Overlay { Detection, Approach, Links, Neighbours, Trails, Ghosts, Contacts, Tints };

struct ViewCommand {
  ViewAction action = ViewAction::Pause;
  std::int64_t count = 0;  // Step, Speed, Select
  ColourMode colour = ColourMode::State;
  Overlay overlay = Overlay::Detection;
  bool on = true;    // Overlay, Panel
  std::string path;  // Screenshot
  // "file:line" of a scripted command; empty for one typed in the window. A scripted command
  // that fails ends the view as an error, where a typed one only shows its message.
  std::string origin;
};

inline ViewCommand view_command(ViewAction action, std::int64_t count = 0) {
  ViewCommand c;
  c.action = action;
  c.count = count;
  return c;
}
inline ViewCommand overlay_command(Overlay overlay, bool on) {
  ViewCommand c;
  c.action = ViewAction::Overlay;
  c.overlay = overlay;
  c.on = on;
  return c;
}

inline ViewCommand record_command(bool on) {
  ViewCommand c;
  c.action = ViewAction::Record;
  c.on = on;
  return c;
}

inline constexpr std::int64_t kMaxStepsPerFrame = 10000;

// One script line (comments after '#', blank lines give no command: returns false). Throws
// InputError naming `where` (file:line) and what was expected.
bool parse_view_command(std::string_view line, const std::string& where, ViewCommand& out);

// Every command of a script file; InputError for an unreadable file or a bad line.
std::vector<ViewCommand> read_view_script(const std::string& path);

std::string_view overlay_name(Overlay overlay);

}  // namespace swarmagg
