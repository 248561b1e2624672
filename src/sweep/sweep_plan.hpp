#pragma once
// What a sweep file describes, checked and in canonical form: a base world, parameter
// values by world key path (a cartesian grid), replicates per grid point and a seed. The
// manifest (sweep.json) stores exactly this, so `merge` rebuilds the same runs without the
// sweep file.
#include <cstdint>
#include <string>
#include <vector>

namespace swarmagg {

struct SweepParameter {
  std::string key;                  // a world key path, e.g. "robots.count"
  std::vector<std::string> values;  // canonical text, as the resolved world writes it
  friend bool operator==(const SweepParameter&, const SweepParameter&) = default;
};

struct SweepPlan {
  std::string name;
  std::uint64_t seed = 1;
  int replicates = 1;
  std::vector<SweepParameter> parameters;  // in sweep-file order; the first varies slowest
  // The resolved base world (world_to_yaml) with run.replicates 1 and no frames; every run's
  // world is this text with the point's parameters and the run's seed applied.
  std::string base_world;
  std::string source;  // where the plan came from, for messages
  // Read back from a sweep's folder (sweep.json, as `merge` reads it): its points were checked
  // against what their controllers and models read when the sweep began, by the version that
  // began it.
  bool recorded = false;
};

}  // namespace swarmagg
