#include "cli/progress_option.hpp"

#include <CLI/CLI.hpp>
#include <iostream>

#include "run/interrupt.hpp"

namespace swarmagg::cli {

void ProgressOption::add_to(CLI::App& command) {
  command
      .add_option("--progress", mode,
                  "auto (default: unless --quiet), always or never; in a log (stderr not a "
                  "terminal) a line every 10 % or 30 s")
      ->check(CLI::IsMember({"auto", "always", "never"}));
}

bool ProgressOption::shown(bool quiet) const {
  return mode == "always" || (mode == "auto" && !quiet);
}

void ProgressOption::phase(bool quiet, const std::string& what, const std::string& doing) const {
  throw_if_interrupted();  // Ctrl-C after the simulation stops before the next phase
  if (shown(quiet)) std::cerr << what << ": " << doing << "...\n" << std::flush;
}

}  // namespace swarmagg::cli
