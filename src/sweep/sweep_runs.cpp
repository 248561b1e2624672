#include "sweep/sweep_runs.hpp"

#include <algorithm>
#include <cstdio>

#include "config/world_loader.hpp"
#include "config/world_override.hpp"

namespace swarmagg {
namespace {

// Folder names stay well below the usual 255-byte limit; a longer id keeps a readable
// prefix and a hash of the whole point so it stays unique.
constexpr std::size_t kMaxIdLength = 200;

std::string point_id(const std::vector<Assignment>& assignments) {
  std::string id;
  for (const auto& [key, value] : assignments) id += (id.empty() ? "" : ",") + key + "=" + value;
  if (id.size() <= kMaxIdLength) return id;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx",
                static_cast<unsigned long long>(text_hash(canonical_point_text(assignments))));
  return id.substr(0, kMaxIdLength - 17) + "~" + hash;
}

// Cross-key checks (check_world) name the world's source, so the source names the point.
WorldSpec point_world(const SweepPlan& plan, const SweepPoint& point) {
  // Swept controller types: a controller key one of them reads is given to every point (the
  // others ignore it); one that none reads is refused at the point.
  std::vector<std::string> types;
  for (const SweepParameter& p : plan.parameters)
    if (p.key == "controller.type") types = p.values;
  std::vector<WorldOverride> overrides = parse_overrides(point_overrides(point));
  for (WorldOverride& o : overrides) {
    // Messages name the sweep file's section, not --set (and a manifest, which names no line).
    o.origin = plan.recorded ? plan.source + ": parameters" : "parameters";
    o.any_controller =
        plan.recorded || std::any_of(types.begin(), types.end(), [&](const std::string& type) {
          return controller_type_reads(type, o.key);
        });
  }
  return load_world_text_with(plan.base_world,
                              plan.source + " (point " + describe_point(point) + ")", overrides);
}

}  // namespace

std::vector<std::string> point_overrides(const SweepPoint& point) {
  std::vector<std::string> result;
  for (const auto& [key, value] : point.assignments) result.push_back(key + "=" + value);
  return result;
}

std::vector<SweepPoint> sweep_points(const std::vector<SweepParameter>& parameters) {
  std::vector<SweepPoint> points(1);
  for (const SweepParameter& parameter : parameters) {
    std::vector<SweepPoint> grown;
    for (const SweepPoint& point : points) {
      for (const std::string& value : parameter.values) {
        SweepPoint next = point;
        next.assignments.emplace_back(parameter.key, value);
        grown.push_back(std::move(next));
      }
    }
    points = std::move(grown);
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].index = static_cast<int>(i);
    points[i].id = point_id(points[i].assignments);
  }
  return points;
}

std::vector<SweepRun> expand_sweep(const SweepPlan& plan) {
  const std::vector<SweepPoint> points = sweep_points(plan.parameters);
  std::vector<SweepRun> runs;
  runs.reserve(points.size() * static_cast<std::size_t>(plan.replicates));
  for (const SweepPoint& point : points) {
    const WorldSpec world = point_world(plan, point);
    for (int k = 0; k < plan.replicates; ++k) {
      SweepRun run;
      run.index = point.index * plan.replicates + k;
      run.point = point;
      run.replicate = k;
      run.seed = sweep_run_seed(plan.seed, point.assignments, k);
      run.world = world;
      run.world.run.seed = run.seed;
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

std::filesystem::path sweep_run_folder(const std::filesystem::path& out, const SweepRun& run) {
  return out / "runs" / run.point.id / ("rep-" + std::to_string(run.replicate));
}

std::string describe_point(const SweepPoint& point) {
  std::string text;
  for (const auto& [key, value] : point.assignments)
    text += (text.empty() ? "" : " ") + key + "=" + value;
  return text;
}

}  // namespace swarmagg
