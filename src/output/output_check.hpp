#pragma once
// Output paths are checked before any work: a run of a day must not end by finding that
// its folder cannot be written. Each check creates what is missing, writes and removes a
// probe file (and the folders it made), and throws InputError naming the option, the path and the
// reason in plain words (exit 2), never a raw filesystem message.
#include <filesystem>
#include <string>

namespace swarmagg {

// `folder` (e.g. --out) exists as a folder, or is created, and a file can be written in it.
void check_output_folder(const std::filesystem::path& folder, const std::string& option);

// `file` (e.g. --video) can be written: its folder is checked as above and `file` is not a
// folder.
void check_output_file(const std::filesystem::path& file, const std::string& option);

// An earlier output is never replaced without a word: its folder holds results someone may
// still need. Throws InputError when `folder` holds files, naming `earlier` (what they are
// likely to be: "an earlier run?") and saying that --force replaces them.
void refuse_to_replace(const std::filesystem::path& folder, const std::string& earlier,
                       const std::string& replaced);

}  // namespace swarmagg
