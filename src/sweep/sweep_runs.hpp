#pragma once
// The runs of a sweep: every point of the parameter grid (first parameter varying slowest)
// times every replicate. Run `index` = point * replicates + replicate; that order is the
// canonical order of merged outputs and what shards divide. Each run's world is the base
// world with the point's parameters, run.replicates 1 and the run's own seed in run.seed,
// so its folder's world.resolved.yaml reproduces it alone with `swarmagg run`.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "sweep/sweep_plan.hpp"
#include "sweep/sweep_seed.hpp"

namespace swarmagg {

struct SweepPoint {
  int index = 0;
  std::vector<Assignment> assignments;  // in sweep-file order
  std::string id;                       // folder name: "robots.count=50,controller.p_leave=0.001"
};

struct SweepRun {
  int index = 0;
  SweepPoint point;
  int replicate = 0;
  std::uint64_t seed = 0;
  WorldSpec world;
};

std::vector<SweepPoint> sweep_points(const std::vector<SweepParameter>& parameters);
// Builds every run's world; a point the world rejects (e.g. too many agents for the arena)
// is an InputError naming the point.
std::vector<SweepRun> expand_sweep(const SweepPlan& plan);

// <out>/runs/<point id>/rep-<replicate>
std::filesystem::path sweep_run_folder(const std::filesystem::path& out, const SweepRun& run);
// The point's parameters as --set takes them: {"robots.count=50", "controller.p_leave=0.001"}.
std::vector<std::string> point_overrides(const SweepPoint& point);
// "robots.count=50 controller.p_leave=0.001", for listings and messages.
std::string describe_point(const SweepPoint& point);

}  // namespace swarmagg
