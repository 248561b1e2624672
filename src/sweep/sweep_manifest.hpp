#pragma once
// sweep.json, written into every sweep output folder before any run starts: the sweep plan
// in canonical form. `merge` rebuilds the runs from it (no sweep file needed) and refuses
// folders whose manifests differ, i.e. shards of different sweeps.
#include <filesystem>
#include <string>

#include "sweep/sweep_plan.hpp"

namespace swarmagg {

inline constexpr const char* kManifestFile = "sweep.json";

std::string manifest_text(const SweepPlan& plan);
// Reads <folder>/sweep.json; a missing or malformed manifest is an InputError.
SweepPlan read_manifest(const std::filesystem::path& folder);

}  // namespace swarmagg
