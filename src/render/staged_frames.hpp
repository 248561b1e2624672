#pragma once
// The frames of a run drawn into a hidden folder inside their frame folder and moved into it
// once the simulation is complete, so that Ctrl-C or a failure leaves the frames an earlier
// run drew there as they were (`run --force` keeps the earlier run whole until the new
// simulation has finished). Inside, not beside: the moves stay on one filesystem whatever the
// frame folder is (a link, a mount), and need no write access to its parent. The hidden
// folder is named as temporary_beside names files, so remove_stale_temporaries of the frame
// folder removes a killed run's. A frame folder made for the staging goes with it unless
// committed, so that a stopped run leaves no empty folder to refuse the next one.
#include <filesystem>

#include "output/made_folders.hpp"

namespace swarmagg {

class StagedFrames {
 public:
  // Makes the frame folder (and the folders above it) where missing.
  explicit StagedFrames(const std::filesystem::path& folder);
  // Removes the staged frames, and the folders made for them, unless committed.
  ~StagedFrames();
  StagedFrames(const StagedFrames&) = delete;
  StagedFrames& operator=(const StagedFrames&) = delete;

  // Where the recorder draws.
  const std::filesystem::path& staging() const { return staging_; }
  // The staged frames replace those of the same number; then the earlier frames beyond them
  // go (other files stay). A failure part way never leaves the folder without frames.
  void commit();

 private:
  std::filesystem::path folder_;
  MadeFolders made_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace swarmagg
