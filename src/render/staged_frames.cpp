#include "render/staged_frames.hpp"

#include <system_error>
#include <utility>

#include "output/atomic_file.hpp"
#include "render/frame_recorder.hpp"

namespace swarmagg {

namespace {

// "renders/x/" names the folder x, as "renders/x" does: the staging folder goes beside it.
std::filesystem::path without_trailing_separator(const std::filesystem::path& folder) {
  const std::filesystem::path normal = folder.lexically_normal();
  return normal.has_filename() || !normal.has_parent_path() ? normal : normal.parent_path();
}

}  // namespace

StagedFrames::StagedFrames(std::filesystem::path folder)
    : folder_(without_trailing_separator(folder)), staging_(temporary_beside(folder_)) {}

StagedFrames::~StagedFrames() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
}

void StagedFrames::commit() {
  std::filesystem::create_directories(folder_);
  for (const std::filesystem::path& earlier : frame_files(folder_))
    std::filesystem::remove(earlier);
  std::error_code none;
  if (std::filesystem::is_directory(staging_, none)) {
    for (const std::filesystem::path& frame : frame_files(staging_))
      std::filesystem::rename(frame, folder_ / frame.filename());
  }
  std::filesystem::remove_all(staging_);
  committed_ = true;
}

}  // namespace swarmagg
