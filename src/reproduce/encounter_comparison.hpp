#pragma once
// Simulated encounter frequency against collision theory (Figs 7-8), from a collision
// world's timeseries.csv: each replicate's final cumulative encounter count divided by the
// run's duration, averaged over replicates; beside it the kinetic prediction
// Z = (4/pi) s v N(N-1)/A (docs/models.md) and the paper's fitted Z = C s v N^2.
#include <filesystem>

#include "config/world_spec.hpp"

namespace swarmagg {

struct EncounterPoint {
  int agents = 0;
  double speed = 0.0;
  double simulated = 0.0;     // mean encounters per tu
  double simulated_sd = 0.0;  // across replicates
  double kinetic = 0.0;
  double paper_fit = 0.0;
};

EncounterPoint measure_encounters(const WorldSpec& world, const std::filesystem::path& run_folder);

}  // namespace swarmagg
