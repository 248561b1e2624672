#include "output/made_folders.hpp"

namespace swarmagg {

namespace {

// The outermost folder of `folder` that does not exist yet (empty when it exists).
std::filesystem::path outermost_missing(const std::filesystem::path& folder) {
  std::error_code ignored;
  std::filesystem::path missing;
  for (std::filesystem::path p = folder; !p.empty() && p != p.parent_path(); p = p.parent_path()) {
    if (std::filesystem::exists(p, ignored)) break;
    missing = p;
  }
  return missing;
}

// Folders above `folder` made again before giving up, when another thread or process keeps
// removing them (each removal is of a folder it made and left empty, so each is brief).
constexpr int kAttempts = 100;

}  // namespace

MadeFolders::MadeFolders(std::filesystem::path folder) : folder_(std::move(folder)) {
  std::error_code error;
  make(error);
  if (error) throw std::filesystem::filesystem_error("cannot create directories", folder_, error);
}

MadeFolders::MadeFolders(std::filesystem::path folder, std::error_code& error)
    : folder_(std::move(folder)) {
  make(error);
}

// Runs of a sweep share the folders above their own, and a failing run removes those it made
// while they are empty (remove_if_empty). A sibling that found such a folder, or made it, can
// see it vanish before it makes its own inside: creating the folder then fails with "no such
// file or directory", and is tried again from the outermost missing folder.
void MadeFolders::make(std::error_code& error) {
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const std::filesystem::path missing = outermost_missing(folder_);
    // The outermost of all attempts: one made in an earlier attempt may still stand.
    if (outermost_made_.empty() ||
        (!missing.empty() && missing.native().size() < outermost_made_.native().size()))
      outermost_made_ = missing;
    error.clear();
    std::filesystem::create_directories(folder_, error);
    if (error != std::errc::no_such_file_or_directory) return;
  }
}

void MadeFolders::remove_if_empty() const noexcept {
  if (outermost_made_.empty()) return;
  std::error_code not_empty;
  for (std::filesystem::path p = folder_; std::filesystem::remove(p, not_empty);
       p = p.parent_path()) {
    if (p == outermost_made_) return;
  }
}

}  // namespace swarmagg
