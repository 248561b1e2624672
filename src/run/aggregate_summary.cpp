#include "run/aggregate_summary.hpp"

#include <map>
#include <optional>

namespace swarmagg {
namespace {

nlohmann::json split_json(const RimSplit& split) {
  return {{"rim", split.rim}, {"inside", split.inside}, {"total", split.total()}};
}

nlohmann::json leave_by_size_json(const LeaveTally& leave, double dt) {
  nlohmann::json rows = nlohmann::json::array();
  for (int m = 2; m <= leave.largest_size(); ++m) {
    const auto k = static_cast<std::size_t>(m);
    if (leave.aggregate_steps_by_size[k] == 0 && leave.attempts_by_size[k] == 0) continue;
    rows.push_back({{"size", m},
                    {"attempts", leave.attempts_by_size[k]},
                    {"escapes", leave.escapes_by_size[k]},
                    {"aggregate_time", leave.aggregate_time(m, dt)}});
  }
  return rows;
}

nlohmann::json aggregates_by_size_json(std::span<const AggregateShape> shapes) {
  struct Sums {
    int count = 0;
    double outer_radius = 0.0;
    double rim = 0.0;
    double member_spacing = 0.0;
  };
  std::map<int, Sums> by_size;
  for (const AggregateShape& shape : shapes) {
    Sums& sums = by_size[shape.size];
    ++sums.count;
    sums.outer_radius += shape.outer_radius;
    sums.rim += shape.rim;
    sums.member_spacing += shape.mean_member_spacing;
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& [size, sums] : by_size) {
    const double n = sums.count;
    rows.push_back({{"size", size},
                    {"count", sums.count},
                    {"mean_outer_radius", sums.outer_radius / n},
                    {"mean_rim", sums.rim / n},
                    {"mean_member_spacing", sums.member_spacing / n}});
  }
  return rows;
}

}  // namespace

std::optional<double> mean_member_spacing(std::span<const AggregateShape> shapes) {
  double sum = 0.0;
  double members = 0.0;
  for (const AggregateShape& shape : shapes) {
    sum += shape.mean_member_spacing * shape.size;
    members += shape.size;
  }
  if (members == 0.0) return std::nullopt;
  return sum / members;
}

void add_aggregate_entries(nlohmann::json& summary, const LeaveTally& leave,
                           std::span<const AggregateShape> final_aggregates, double dt) {
  const std::optional<double> spacing = mean_member_spacing(final_aggregates);
  summary["final"]["mean_member_spacing"] = spacing ? nlohmann::json(*spacing) : nlohmann::json();
  summary["leave_attempts"] = split_json(leave.attempts);
  summary["escapes"] = split_json(leave.escapes);
  summary["aggregates_by_size"] = aggregates_by_size_json(final_aggregates);
  summary["leave_by_size"] = leave_by_size_json(leave, dt);
}

LeaveTally pooled_leave(const RunResult& result) {
  LeaveTally pooled;
  for (const ReplicateOutcome& r : result.replicates) pooled += r.leave;
  return pooled;
}

std::vector<AggregateShape> pooled_final_aggregates(const RunResult& result) {
  std::vector<AggregateShape> pooled;
  for (const ReplicateOutcome& r : result.replicates)
    pooled.insert(pooled.end(), r.final_aggregates.begin(), r.final_aggregates.end());
  return pooled;
}

}  // namespace swarmagg
