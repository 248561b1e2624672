#pragma once
// An output that fails leaves no empty folders behind: a writer that makes the folders of
// its output remembers the outermost one it made, and removes what it made again when the
// output is refused or interrupted before any file landed there.
#include <exception>
#include <filesystem>
#include <system_error>

namespace swarmagg {

class MadeFolders {
 public:
  // Creates `folder` and the missing folders above it (errors as create_directories: thrown,
  // or in `error` with the second form). A folder above that another MadeFolders removes
  // meanwhile (its own, left empty on failure) is made again.
  explicit MadeFolders(std::filesystem::path folder);
  MadeFolders(std::filesystem::path folder, std::error_code& error);

  // Removes the folders made, innermost first, while they are empty: a folder holding a file
  // (someone else's, or one written after all) stays, and so do the folders above it.
  void remove_if_empty() const noexcept;

 private:
  void make(std::error_code& error);

  std::filesystem::path folder_;
  std::filesystem::path outermost_made_;  // empty when `folder` existed
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
