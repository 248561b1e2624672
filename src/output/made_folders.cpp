#include "output/made_folders.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <vector>

namespace swarmagg {

namespace {

// A folder the race below keeps removing is made again this many times at most. Each removal
// needs a sibling to fail while the folder is empty, so a folder that vanishes this often
// vanishes for another reason (its working folder deleted, say), and the error is reported.
constexpr int kAttempts = 100;

// `folder` and the folders above it, the outermost first.
std::vector<std::filesystem::path> folder_chain(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> chain;
  for (std::filesystem::path p = folder; !p.empty() && p != p.parent_path(); p = p.parent_path())
    chain.push_back(p);
  std::reverse(chain.begin(), chain.end());
  return chain;
}

// The index of the outermost folder of `chain` missing below the innermost one that exists.
std::size_t first_missing(const std::vector<std::filesystem::path>& chain) {
  std::error_code ignored;
  std::size_t level = chain.size();
  while (level > 0 && !std::filesystem::is_directory(chain[level - 1], ignored)) --level;
  return level;
}

}  // namespace

int make_one_folder(const std::filesystem::path& folder) {
  return ::mkdir(folder.c_str(), 0777) == 0 ? 0 : errno;
}

// Runs of a sweep share the folders above their own, and a failing run removes those it made
// while they are empty (MadeFolders::remove_if_empty). A folder found there (or just made by a
// sibling: EEXIST) can vanish before the next one is made inside it, which then fails with
// ENOENT: the chain is made again from the first missing folder. create_directories would
// report that ENOENT, or an EEXIST for a folder that vanished between its mkdir and its check.
std::filesystem::path make_folders(const std::filesystem::path& folder, std::error_code& error,
                                   const FolderMaker& make_one) {
  const std::vector<std::filesystem::path> chain = folder_chain(folder);
  std::size_t outermost_made = chain.size();
  const auto made = [&] {
    return outermost_made < chain.size() ? chain[outermost_made] : std::filesystem::path();
  };
  error = std::make_error_code(std::errc::no_such_file_or_directory);
  for (int attempt = 0; attempt < kAttempts && !chain.empty(); ++attempt) {
    std::size_t level = first_missing(chain);
    for (; level < chain.size(); ++level) {
      const int failure = make_one(chain[level]);
      if (failure == 0) outermost_made = std::min(outermost_made, level);
      if (failure == ENOENT) break;
      if (failure != 0 && failure != EEXIST) {
        error.assign(failure, std::generic_category());
        return made();
      }
    }
    if (level < chain.size()) continue;  // a folder above vanished
    // EEXIST also answers for a file of that name.
    std::error_code ignored;
    error = std::filesystem::is_directory(folder, ignored)
                ? std::error_code()
                : std::make_error_code(std::errc::file_exists);
    return made();
  }
  return made();
}

MadeFolders::MadeFolders(std::filesystem::path folder) : folder_(std::move(folder)) {
  std::error_code error;
  outermost_made_ = make_folders(folder_, error);
  if (error) throw std::filesystem::filesystem_error("cannot create directories", folder_, error);
}

MadeFolders::MadeFolders(std::filesystem::path folder, std::error_code& error)
    : folder_(std::move(folder)), outermost_made_(make_folders(folder_, error)) {}

void MadeFolders::remove_if_empty() const noexcept {
  if (outermost_made_.empty()) return;
  std::error_code not_empty;
  for (std::filesystem::path p = folder_; std::filesystem::remove(p, not_empty);
       p = p.parent_path()) {
    if (p == outermost_made_) return;
  }
}

}  // namespace swarmagg
