#include "render/staged_frames.hpp"

#include <set>
#include <system_error>

#include "output/atomic_file.hpp"
#include "render/frame_recorder.hpp"

namespace swarmagg {

StagedFrames::StagedFrames(const std::filesystem::path& folder)
    : folder_(folder), made_(folder), staging_(temporary_beside(folder / "staged-frames")) {}

StagedFrames::~StagedFrames() {
  if (committed_) return;
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
  made_.remove_if_empty();
}

void StagedFrames::commit() {
  std::set<std::filesystem::path> drawn;
  std::error_code none;
  if (std::filesystem::is_directory(staging_, none)) {
    for (const std::filesystem::path& frame : frame_files(staging_)) {
      std::filesystem::rename(frame, folder_ / frame.filename());
      drawn.insert(frame.filename());
    }
  }
  for (const std::filesystem::path& earlier : frame_files(folder_)) {
    if (!drawn.contains(earlier.filename())) std::filesystem::remove(earlier);
  }
  std::filesystem::remove_all(staging_);
  committed_ = true;
}

}  // namespace swarmagg
