#pragma once
// An output that fails leaves no empty folders behind: a writer that makes the folders of
// its output remembers the outermost one it made, and removes what it made again when the
// output is refused or interrupted before any file landed there.
#include <exception>
#include <filesystem>
#include <functional>
#include <system_error>

namespace swarmagg {

// Makes one folder (the mkdir system call): 0, or the errno it failed with.
using FolderMaker = std::function<int(const std::filesystem::path&)>;
int make_one_folder(const std::filesystem::path& folder);

// Makes `folder` and the missing folders above it, as create_directories does, and returns the
// outermost one it made (empty: none). A folder above that vanishes meanwhile (another run's,
// removed while empty because that run failed) is made again. `make_one` is the system's
// mkdir but in tests.
std::filesystem::path make_folders(const std::filesystem::path& folder, std::error_code& error,
                                   const FolderMaker& make_one = make_one_folder);

class MadeFolders {
 public:
  // Creates `folder` and the missing folders above it (make_folders; errors thrown as
  // create_directories throws them, or in `error` with the second form).
  explicit MadeFolders(std::filesystem::path folder);
  MadeFolders(std::filesystem::path folder, std::error_code& error);

  // Removes the folders made, innermost first, while they are empty: a folder holding a file
  // (someone else's, or one written after all) stays, and so do the folders above it.
  void remove_if_empty() const noexcept;

 private:
  std::filesystem::path folder_;
  std::filesystem::path outermost_made_;  // empty when this object made no folder
};

// Removes the folders `made` made (while empty) when the scope it guards is left by an
// exception (an error, Ctrl-C), and keeps them when it ends normally.
class RemovedOnFailure {
 public:
  explicit RemovedOnFailure(const MadeFolders& made)
      : made_(made), exceptions_(std::uncaught_exceptions()) {}
  ~RemovedOnFailure() {
    if (std::uncaught_exceptions() > exceptions_) made_.remove_if_empty();
  }
  RemovedOnFailure(const RemovedOnFailure&) = delete;
  RemovedOnFailure& operator=(const RemovedOnFailure&) = delete;

 private:
  const MadeFolders& made_;
  int exceptions_;
};

}  // namespace swarmagg
