#pragma once
// The frames of a run drawn into a hidden folder beside their frame folder and moved into it
// once the simulation is complete, so that Ctrl-C or a failure leaves the frames an earlier
// run drew there as they were (`run --force` keeps the earlier run whole until the new
// simulation has finished). The hidden folder is named as temporary_beside names files, so a
// killed run's is removed by remove_stale_temporaries.
#include <filesystem>

namespace swarmagg {

class StagedFrames {
 public:
  explicit StagedFrames(std::filesystem::path folder);
  // Removes the staged frames unless committed.
  ~StagedFrames();
  StagedFrames(const StagedFrames&) = delete;
  StagedFrames& operator=(const StagedFrames&) = delete;

  // Where the recorder draws.
  const std::filesystem::path& staging() const { return staging_; }
  // The earlier frames in the frame folder go (other files stay), the staged ones take their
  // place.
  void commit();

 private:
  std::filesystem::path folder_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace swarmagg
