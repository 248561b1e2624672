#pragma once
// `swarmagg sweep --list`: one line per run (index, replicate, seed, status, parameters)
// under a header, without running anything.
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_runs.hpp"

namespace swarmagg {

std::string sweep_listing(const std::vector<SweepRun>& runs, const std::filesystem::path& out);

}  // namespace swarmagg
