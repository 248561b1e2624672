#pragma once
// The commands a message tells the user to run next in a run's folder (adding the rates or the
// model a run left out, redrawing plots), written so that they can be pasted into a shell.
#include <filesystem>
#include <string>

namespace swarmagg::cli {

// A path as one word of a POSIX shell command: as it is when plain, else in single quotes; a
// relative path starting with '-' gains "./", so that it is not read as an option.
std::string shell_word(const std::string& text);

// What the rates and model of the run in `folder` need: rates.csv when the folder holds one or
// the model needs measured rates (`rates_needed`), made first by `swarmagg rates` when it is
// missing. Returns "swarmagg [rates ... && swarmagg ]model ... --out FOLDER", or only the
// rates command without `model`.
std::string rates_and_model_commands(const std::filesystem::path& folder, bool rates_needed,
                                     bool model = true);

}  // namespace swarmagg::cli
