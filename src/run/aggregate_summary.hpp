#pragma once
// The summary.json entries of the aggregates' geometry and the LEAVE episodes, the same for
// one replicate and for the replicates pooled:
//   leave_attempts, escapes: {rim, inside, total}
//   final.mean_member_spacing: mean over every member of a final aggregate of the distance
//     to its nearest fellow member (null without aggregates)
//   aggregates_by_size: [{size, count, mean_outer_radius, mean_rim, mean_member_spacing}]
//     over the final aggregates
//   leave_by_size: [{size, attempts, escapes, aggregate_time}] over the whole run, where
//     aggregate_time is the summed tu that aggregates of that size existed
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <vector>

#include "observers/aggregate_geometry.hpp"
#include "observers/leave_tally.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

// Member-weighted, so every member counts once; nullopt without aggregates.
std::optional<double> mean_member_spacing(std::span<const AggregateShape> shapes);

// Adds the entries above to `summary` (a replicate's or the pooled object).
void add_aggregate_entries(nlohmann::json& summary, const LeaveTally& leave,
                           std::span<const AggregateShape> final_aggregates, double dt);

// Every replicate's tally added up, and every replicate's final aggregates.
LeaveTally pooled_leave(const RunResult& result);
std::vector<AggregateShape> pooled_final_aggregates(const RunResult& result);

}  // namespace swarmagg
