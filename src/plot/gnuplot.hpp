#pragma once
// Plots are gnuplot scripts (.gp) kept beside the CSV they read, so users can restyle and
// re-run them; run_gnuplot renders one to PNG with the gnuplot program (Debian
// gnuplot-nox), run directly (no shell) from the script's own folder.
#include <filesystem>
#include <string>

namespace swarmagg {

// True when a gnuplot executable is on PATH.
bool gnuplot_available();

// Writes `script` to `script_path` (atomically) and runs gnuplot on it with the script's
// folder as working directory, so the script names its CSV and PNG files relatively.
// Throws std::runtime_error with gnuplot's own messages when it fails or is missing (the
// message says how to install it). While a GnuplotBatch is open on this thread, the script
// is written and queued instead, and the batch draws it (plot/gnuplot_batch.hpp).
void run_gnuplot(const std::filesystem::path& script_path, const std::string& script);

// Quotes text for a gnuplot string literal ('...'), never substituted or run.
std::string gnuplot_quote(const std::string& text);

}  // namespace swarmagg
