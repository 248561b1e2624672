#pragma once
// --progress auto|always|never, shared by the commands that simulate or compute the models
// (`model`: run/model_progress.hpp). auto: progress unless --quiet; always: even with
// --quiet; never: none. On a terminal it is one line rewritten in place, in a log a plain
// line every 10 % or 30 s (run/progress_line.hpp). The phases after the simulation (models,
// plots, merging) say what they do on the same stream.
#include <string>

namespace CLI {
class App;
}  // namespace CLI

namespace swarmagg::cli {

struct ProgressOption {
  std::string mode = "auto";

  void add_to(CLI::App& command);
  bool shown(bool quiet) const;
  // "<what>: <doing>..." on stderr when progress is shown; first throws Interrupted when a
  // signal arrived, so that no phase starts after Ctrl-C.
  void phase(bool quiet, const std::string& what, const std::string& doing) const;
};

}  // namespace swarmagg::cli
