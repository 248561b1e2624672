#pragma once
// The facts `reproduce` reads from a run folder's summary.json beside its CSVs.
#include <filesystem>
#include <optional>

namespace swarmagg {

// What a run folder's summary.json says of its aggregates, pooled over the replicates.
struct RunSummaryFacts {
  std::optional<double> member_spacing;  // final mean member spacing (none without aggregates)
  // The share of LEAVE attempts made by a member with its fellows all around it (not on the
  // rim); none when nobody tried to leave.
  std::optional<double> inside_attempt_share;
};
RunSummaryFacts run_summary_facts(const std::filesystem::path& run_folder);

}  // namespace swarmagg
