#include "run/trajectory_output.hpp"

#include <optional>

#include "output/trajectory_layout.hpp"
#include "run/replicate.hpp"
#include "run/run_folder.hpp"

namespace swarmagg {
namespace {

class TrajectoryObserver final : public ReplicateObserver {
 public:
  TrajectoryObserver(TrajectoryWriter& writer, int every) : writer_(writer), every_(every) {}

  void observe(const Replicate& replicate) override {
    // The datasets are made at the first observation, when the replicate's seed is known.
    if (!trajectory_)
      trajectory_.emplace(writer_.begin_replicate(replicate.index(), replicate.seed()));
    if (replicate.steps_done() % every_ == 0) {
      trajectory_->record(replicate.snapshot(), replicate.swarm().heading);
    }
  }
  void finish() override {
    if (trajectory_) trajectory_->finish();
  }

 private:
  TrajectoryWriter& writer_;
  int every_;
  std::optional<ReplicateTrajectory> trajectory_;
};

}  // namespace

std::unique_ptr<TrajectoryWriter> trajectory_writer(const WorldSpec& spec,
                                                    const std::filesystem::path& out) {
  if (spec.run.trajectories <= 0) return nullptr;
  return std::make_unique<TrajectoryWriter>(spec, resolved_world_text(spec),
                                            out / trajectory_layout::kFileName);
}

std::unique_ptr<ReplicateObserver> trajectory_observer(TrajectoryWriter& writer, int every) {
  return std::make_unique<TrajectoryObserver>(writer, every);
}

ObserverFactory trajectory_observers(TrajectoryWriter* writer, int every) {
  if (writer == nullptr) return nullptr;
  return [writer, every](int) { return trajectory_observer(*writer, every); };
}

}  // namespace swarmagg
