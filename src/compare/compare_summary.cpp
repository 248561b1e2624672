#include "compare/compare_summary.hpp"

#include <optional>
#include <sstream>

#include "output/format_text.hpp"

namespace swarmagg {
namespace {

// A fraction of no attempts is none: "-" in the text, null in the JSON (0 read as "none got
// out").
std::optional<double> fraction(std::int64_t part, std::int64_t whole) {
  if (whole <= 0) return std::nullopt;
  return static_cast<double>(part) / static_cast<double>(whole);
}

std::string fraction_text(std::int64_t part, std::int64_t whole) {
  const std::optional<double> f = fraction(part, whole);
  return f ? format_text("%.3f", *f) : "-";
}

nlohmann::json fraction_json(std::int64_t part, std::int64_t whole) {
  const std::optional<double> f = fraction(part, whole);
  return f ? nlohmann::json(*f) : nlohmann::json(nullptr);
}

constexpr const char* kRimRuleText =
    "docs/models.md: rim = fewer than 6 fellow members within 1.2 x spacing when the attempt "
    "starts";

const char* verdict(double p) {
  return p < kSignificance ? "different" : "no significant difference";
}

constexpr const char* kKsMethod =
    "exact (lattice walk) when the two samples' sizes multiply to 10^7 or less, else the "
    "asymptotic Kolmogorov series with Stephens' correction; conservative with ties";
constexpr const char* kNoAggregates = "an arm ended with no aggregate";
constexpr const char* kNoAttempts = "an arm has fewer than two replicates with LEAVE attempts";

std::string judged(bool differs) {
  return differs ? "different" : "no significant difference";
}

void leave_line(std::ostringstream& out, const ArmSummary& arm) {
  const RimSplit& tried = arm.leave.attempts;
  const RimSplit& out_of = arm.leave.escapes;
  out << "  " << arm.label << ": rim " << out_of.rim << "/" << tried.rim << " got out ("
      << fraction_text(out_of.rim, tried.rim) << "), inside " << out_of.inside << "/"
      << tried.inside << " (" << fraction_text(out_of.inside, tried.inside) << ")\n";
}

nlohmann::json leave_json(const LeaveTally& l) {
  return {{"rim_attempts", l.attempts.rim},
          {"rim_got_out", l.escapes.rim},
          {"rim_fraction_out", fraction_json(l.escapes.rim, l.attempts.rim)},
          {"inside_attempts", l.attempts.inside},
          {"inside_got_out", l.escapes.inside},
          {"inside_fraction_out", fraction_json(l.escapes.inside, l.attempts.inside)}};
}

// "<what>: a <mean +- half width>, b <...> (Welch, p = ...)" for a quantity measured per
// replicate, each side's mean and half width printed with `mean_and_half`.
void welch_line(std::ostringstream& out, const char* what, const Comparison& c,
                MeanInterval ArmSummary::*quantity, const WelchResult& w,
                const char* mean_and_half) {
  const MeanInterval& a = c.a.*quantity;
  const MeanInterval& b = c.b.*quantity;
  out << what << ": " << c.a.label << format_text(mean_and_half, a.mean, a.half_width) << ", "
      << c.b.label << format_text(mean_and_half, b.mean, b.half_width)
      << format_text(" (Welch, p = %.3g)\n", w.p_value);
}

// The replicates' mean of one lineage count.
double mean_count(const std::vector<LineageCounts>& lineage, std::uint64_t LineageCounts::*count) {
  double sum = 0.0;
  for (const LineageCounts& l : lineage) sum += static_cast<double>(l.*count);
  return lineage.empty() ? 0.0 : sum / static_cast<double>(lineage.size());
}

void lineage_line(std::ostringstream& out, const ArmSummary& arm) {
  out << "  " << arm.label << ": births "
      << format_text("%.2f", mean_count(arm.lineage, &LineageCounts::births)) << ", deaths "
      << format_text("%.2f", mean_count(arm.lineage, &LineageCounts::deaths)) << ", merges "
      << format_text("%.2f", mean_count(arm.lineage, &LineageCounts::merges)) << ", splits "
      << format_text("%.2f", mean_count(arm.lineage, &LineageCounts::splits)) << "\n";
}

nlohmann::json lineage_json(const ArmSummary& arm) {
  nlohmann::json counts = nlohmann::json::object();
  for (const auto& [name, count] :
       {std::pair{"births", &LineageCounts::births}, std::pair{"deaths", &LineageCounts::deaths},
        std::pair{"merges", &LineageCounts::merges}, std::pair{"splits", &LineageCounts::splits}}) {
    std::vector<std::uint64_t> values;
    for (const LineageCounts& l : arm.lineage) values.push_back(l.*count);
    counts[name] = values;
  }
  counts["net_merges_per_tu"] = arm.net_merge_rates;
  counts["mean_net_merges_per_tu"] = arm.net_merge_rate.mean;
  counts["net_merges_per_tu_ci95_half_width"] = arm.net_merge_rate.half_width;
  return counts;
}

nlohmann::json welch_json(const WelchResult& w) {
  return {{"b_minus_a", w.difference},
          {"ci95", {w.low, w.high}},
          {"welch_dof", w.dof},
          {"p_value", w.p_value}};
}

nlohmann::json arm_json(const ArmSummary& arm) {
  return {{"label", arm.label},
          {"final_noa", arm.final_noa},
          {"mean_final_noa", arm.noa.mean},
          {"mean_final_noa_ci95_half_width", arm.noa.half_width},
          {"final_aggregates", arm.final_sizes.size()},
          {"encounter_rates_per_tu", arm.encounter_rates},
          {"mean_encounter_rate_per_tu", arm.encounter_rate.mean},
          {"encounter_rate_ci95_half_width", arm.encounter_rate.half_width},
          {"leave_attempts", leave_json(arm.leave)},
          {"lineage", lineage_json(arm)}};
}

nlohmann::json ks_json(const KsResult& ks) {
  return {{"statistic", ks.statistic},
          {"p_value", ks.p_value},
          {"n_a", ks.n_a},
          {"n_b", ks.n_b},
          {"p_value_exact", ks.exact}};
}

}  // namespace

std::string comparison_text(const std::string& world_name, const Comparison& c) {
  std::ostringstream out;
  const WelchResult& w = c.noa_difference;
  out << world_name << ": " << c.a.label << " vs " << c.b.label << ", " << c.a.final_noa.size()
      << " replicates each, same seeds\n";
  out << "mean final NOA: " << c.a.label
      << format_text(" %.2f +- %.2f", c.a.noa.mean, c.a.noa.half_width) << ", " << c.b.label
      << format_text(" %.2f +- %.2f (95%% CI)\n", c.b.noa.mean, c.b.noa.half_width);
  out << "difference (" << c.b.label << " - " << c.a.label << ")"
      << format_text(" %.2f, 95%% CI [%.2f, %.2f]", w.difference, w.low, w.high)
      // Two arms without spread have no degrees of freedom to print (it read "df 0.0").
      << (w.dof > 0.0 ? format_text(" (Welch, df %.1f, p = %.3g): ", w.dof, w.p_value)
                      : format_text(" (no spread in either arm, p = %.3g): ", w.p_value))
      << verdict(w.p_value) << "\n";
  out << "KS final NOA:"
      << format_text(" D = %.3f, p = %.3g: ", c.ks_noa.statistic, c.ks_noa.p_value)
      << verdict(c.ks_noa.p_value) << "\n";
  out << "KS final aggregate sizes (" << c.ks_sizes.n_a << " vs " << c.ks_sizes.n_b
      << " aggregates):";
  if (c.sizes_judged()) {
    out << format_text(" D = %.3f, p = %.3g: ", c.ks_sizes.statistic, c.ks_sizes.p_value)
        << verdict(c.ks_sizes.p_value) << "\n";
  } else {
    out << " not judged (" << kNoAggregates << ")\n";
  }
  out << "  (KS p-values: " << kKsMethod << ")\n";
  welch_line(out, "encounters per tu", c, &ArmSummary::encounter_rate, c.encounter_rate_difference,
             " %.2f +- %.2f");
  const ProportionResult& f = c.escape_fraction;
  if (c.has_leaving) {
    out << "LEAVE attempts that got out (" << kRimRuleText << "):\n";
    leave_line(out, c.a);
    leave_line(out, c.b);
    if (c.escape_fraction_judged()) {
      out << "  escape fraction: " << c.a.label << format_text(" %.3f, ", f.fraction_a) << c.b.label
          << format_text(" %.3f (Welch on the replicates' spread, p = %.3g)\n", f.fraction_b,
                         f.p_value);
    } else {
      out << "  escape fraction: not judged (" << kNoAttempts << ")\n";
    }
  }
  out << "where the aggregates came from, mean per replicate over the run (final NOA = births - "
         "deaths - merges + splits; the models have no merges or splits):\n";
  lineage_line(out, c.a);
  lineage_line(out, c.b);
  welch_line(out, "  net merges (merges - splits) per tu", c, &ArmSummary::net_merge_rate,
             c.net_merge_rate_difference, " %.4f +- %.4f");
  out << format_text("verdicts at the %.0f%% level (per test), one per quantity:\n",
                     100.0 * (1.0 - kSignificance));
  out << "  final NOA: " << judged(c.noa_differs()) << " (Welch on the mean, KS on NOA"
      << (c.sizes_judged() ? " and sizes)\n" : ")\n");
  out << "  encounter rate: " << judged(c.encounter_rate_differs()) << " (Welch)\n";
  out << "  escape fraction: "
      << (c.escape_fraction_judged()
              ? judged(c.escape_fraction_differs()) +
                    std::string(" (Welch on the replicates' spread)")
              : std::string("not judged (") +
                    (c.has_leaving ? kNoAttempts : "no agent leaves in this world") + ")")
      << "\n";
  out << "  net merge rate: " << judged(c.net_merge_rate_differs()) << " (Welch)\n";
  return out.str();
}

nlohmann::json comparison_json(const std::string& world_name, const Comparison& c) {
  const WelchResult& w = c.noa_difference;
  return {{"world", world_name},
          {"a", arm_json(c.a)},
          {"b", arm_json(c.b)},
          {"final_noa_difference", welch_json(w)},
          {"ks_final_noa", ks_json(c.ks_noa)},
          {"ks_final_aggregate_sizes", ks_json(c.ks_sizes)},
          {"ks_final_aggregate_sizes_judged", c.sizes_judged()},
          {"ks_p_value_method", kKsMethod},
          {"rim_rule", std::string(kRimRuleText) +
                           "; got out: perceives (within s) no still-waiting member of the "
                           "aggregate it left when its LEAVE timeout ends"},
          {"encounter_rate_difference", welch_json(c.encounter_rate_difference)},
          {"net_merge_rate_difference", welch_json(c.net_merge_rate_difference)},
          {"escape_fraction",
           {{"a", c.escape_fraction.fraction_a},
            {"b", c.escape_fraction.fraction_b},
            {"t", c.escape_fraction.t},
            {"dof", c.escape_fraction.dof},
            {"p_value", c.escape_fraction.p_value},
            {"judged", c.escape_fraction_judged()}}},
          {"has_leaving", c.has_leaving},
          {"significance", kSignificance},
          {"verdicts",
           {{"final_noa", judged(c.noa_differs())},
            {"encounter_rate", judged(c.encounter_rate_differs())},
            {"escape_fraction", c.escape_fraction_judged() ? judged(c.escape_fraction_differs())
                                                           : std::string("not judged")},
            {"net_merge_rate", judged(c.net_merge_rate_differs())}}},
          {"differs", c.differs()}};
}

}  // namespace swarmagg
