#include "reproduce/run_summary_facts.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

namespace swarmagg {

RunSummaryFacts run_summary_facts(const std::filesystem::path& run_folder) {
  std::ifstream in(run_folder / "summary.json");
  if (!in) return {};
  // A damaged summary, or one of another tool, gives what it holds as numbers, no more.
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  const auto number_at = [&summary](const nlohmann::json::json_pointer& at) {
    const nlohmann::json* value = summary.contains(at) ? &summary.at(at) : nullptr;
    return value && value->is_number() ? std::optional<double>(value->get<double>()) : std::nullopt;
  };
  if (!summary.is_object()) return {};
  RunSummaryFacts facts;
  facts.member_spacing =
      number_at(nlohmann::json::json_pointer("/pooled/final/mean_member_spacing"));
  const std::optional<double> inside =
      number_at(nlohmann::json::json_pointer("/pooled/leave_attempts/inside"));
  const std::optional<double> total =
      number_at(nlohmann::json::json_pointer("/pooled/leave_attempts/total"));
  if (inside && total && *total > 0.0) facts.inside_attempt_share = *inside / *total;
  return facts;
}

}  // namespace swarmagg
