#pragma once
// Wires trajectories.h5 into a run (run.trajectories = K > 0): one writer for the run, and
// an observer per replicate that stores every K-th step, starting at step 0.
#include <filesystem>
#include <memory>

#include "config/world_spec.hpp"
#include "output/trajectory_writer.hpp"
#include "run/replicate_observer.hpp"

namespace swarmagg {

// The writer of <out>/trajectories.h5, or nullptr when run.trajectories is 0.
std::unique_ptr<TrajectoryWriter> trajectory_writer(const WorldSpec& spec,
                                                    const std::filesystem::path& out);

// An observer recording one replicate into `writer`, which must outlive it.
std::unique_ptr<ReplicateObserver> trajectory_observer(TrajectoryWriter& writer, int every);
// Observers recording into `writer` (none when it is null); it must outlive the run.
ObserverFactory trajectory_observers(TrajectoryWriter* writer, int every);

}  // namespace swarmagg
