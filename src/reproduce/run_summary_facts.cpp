#include "reproduce/run_summary_facts.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

namespace swarmagg {

RunSummaryFacts run_summary_facts(const std::filesystem::path& run_folder) {
  std::ifstream in(run_folder / "summary.json");
  if (!in) return {};
  // Not const: operator[] of a missing key then gives null instead of undefined behaviour.
  nlohmann::json summary = nlohmann::json::parse(in);
  nlohmann::json& pooled = summary["pooled"];
  RunSummaryFacts facts;
  const nlohmann::json& spacing = pooled["final"]["mean_member_spacing"];
  if (spacing.is_number()) facts.member_spacing = spacing.get<double>();
  const nlohmann::json& attempts = pooled["leave_attempts"];
  if (attempts.is_object() && attempts.value("total", 0.0) > 0.0)
    facts.inside_attempt_share = attempts.value("inside", 0.0) / attempts.value("total", 0.0);
  return facts;
}

}  // namespace swarmagg
