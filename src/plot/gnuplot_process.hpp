#pragma once
// Runs the gnuplot program on one command file, from a given working folder, and collects
// what it printed: the part of run_gnuplot and GnuplotBatch that starts processes.
#include <filesystem>
#include <string>

namespace swarmagg {

// gnuplot's path on PATH, or empty when it is not installed.
std::filesystem::path find_gnuplot();

struct GnuplotExit {
  bool succeeded = false;
  std::string messages;  // gnuplot's stdout and stderr
};

// Runs `gnuplot command_file` in `folder`. Throws std::runtime_error when gnuplot is
// missing or cannot be started; a script error is a GnuplotExit that did not succeed.
GnuplotExit run_gnuplot_process(const std::filesystem::path& command_file,
                                const std::filesystem::path& folder);

// The error for a script gnuplot is not installed to draw.
std::string gnuplot_missing_message(const std::filesystem::path& script_path);

}  // namespace swarmagg
