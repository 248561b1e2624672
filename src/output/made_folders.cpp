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

}  // namespace

MadeFolders::MadeFolders(std::filesystem::path folder)
    : folder_(std::move(folder)), outermost_made_(outermost_missing(folder_)) {
  std::filesystem::create_directories(folder_);
}

MadeFolders::MadeFolders(std::filesystem::path folder, std::error_code& error)
    : folder_(std::move(folder)), outermost_made_(outermost_missing(folder_)) {
  std::filesystem::create_directories(folder_, error);
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
