#pragma once
// Runs a world into its folder unless the folder already holds a complete run of the same
// resolved world by the same build, so re-plotting and re-reporting are instant.
// world.resolved.yaml is written last by write_run_folder, so its presence marks a complete
// run; its text must be the one this build writes for the world, comments included (the
// swarmagg version and commit, the seeds): runs of an older build are made again.
#include <filesystem>

#include "config/world_spec.hpp"
#include "rates/rate_outputs.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

// True when `folder` holds a complete run of exactly `spec` by this build, with its model
// outputs.
bool run_is_reusable(const WorldSpec& spec, const std::filesystem::path& folder);

// Runs the world and writes the run folder, its measured rates (rates.csv, rates.json,
// the rate plots' scripts, drawn when `rate_plots` says so) and its model outputs
// (model.csv, model-timeseries/, with the measured variants) unless run_is_reusable.
// Returns true when the run was reused.
bool ensure_run(const WorldSpec& spec, const std::filesystem::path& folder,
                const RunOptions& options, RatePlots rate_plots = RatePlots::ScriptsOnly);

}  // namespace swarmagg
