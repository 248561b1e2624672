#pragma once
// Whether a run of a sweep is done. write_run_folder writes world.resolved.yaml last, after
// every other output was written atomically, so a run is complete exactly when that file
// exists and holds the run's world (but for run.threads and render.*, which change none of its
// outputs). A folder without it is an unfinished attempt; one whose world differs (the base
// world or the sweep changed) is outdated. Both are run again.
#include <filesystem>

#include "sweep/sweep_runs.hpp"

namespace swarmagg {

enum class RunStatus { Pending, Unfinished, Outdated, Complete };

RunStatus sweep_run_status(const std::filesystem::path& out, const SweepRun& run);
const char* status_name(RunStatus status);

}  // namespace swarmagg
