#include "reproduce/compaction_report.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "analysis/variant_error.hpp"
#include "reproduce/report.hpp"

namespace swarmagg {
namespace {

using Quantity = std::function<OnOff(const CompactionEffect&)>;

std::string cell(double value) {
  return std::isnan(value) ? "-" : report_number(value);
}

std::string pair_cells(const OnOff& value) {
  return cell(value.on) + " | " + cell(value.off);
}

// The paper's second variant of the effect's model: collision (Bayindir) or peripheral.
std::string second_variant(const CompactionEffect& e) {
  return e.bayindir ? "collision" : "peripheral";
}

std::string error_table(const std::vector<CompactionEffect>& effects) {
  std::string text =
      "| Fig | world | error | original on | original off | collision / peripheral on | "
      "collision / peripheral off | measured on | measured off |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const CompactionEffect& e : effects) {
    text += "| " + e.figures + " | " + e.world + " | " + (e.bayindir ? "NOA RMSE" : "TV") + " | " +
            pair_cells(e.error("original")) + " | " + pair_cells(e.error(second_variant(e))) +
            " | " + pair_cells(e.error(kMeasuredVariant)) + " |\n";
  }
  return text;
}

std::string simulation_table(const std::vector<CompactionEffect>& effects) {
  std::string text =
      "| Fig | world | final mean NOA on | off | member spacing on | off | growths / model on | "
      "off | escapes / attempts on | off |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CompactionEffect& e : effects) {
    text += "| " + e.figures + " | " + e.world + " | " + pair_cells(e.final_noa) + " | " +
            pair_cells(e.member_spacing) + " | " + pair_cells(e.growth_vs_model) + " | " +
            pair_cells(e.escape_fraction) + " |\n";
  }
  return text;
}

// The values of a quantity over the effects that have it both ways.
struct Spread {
  std::vector<OnOff> values;
  int lower_on = 0;   // worlds where the value is lower with compaction on
  int higher_on = 0;  // and higher
  double min_on = INFINITY, max_on = -INFINITY, min_off = INFINITY, max_off = -INFINITY;
  bool empty() const { return values.empty(); }
  int count() const { return static_cast<int>(values.size()); }
  double median_ratio() const {  // of on / off (NaN where an off value is 0)
    std::vector<double> ratios;
    for (const OnOff& v : values) ratios.push_back(v.on / v.off);
    std::sort(ratios.begin(), ratios.end());
    const std::size_t n = ratios.size();
    return n % 2 ? ratios[n / 2] : 0.5 * (ratios[n / 2 - 1] + ratios[n / 2]);
  }
};

Spread spread_of(const std::vector<CompactionEffect>& effects, const Quantity& quantity,
                 const std::function<bool(const CompactionEffect&)>& keep = nullptr) {
  Spread s;
  for (const CompactionEffect& e : effects) {
    const OnOff v = quantity(e);
    if ((keep && !keep(e)) || std::isnan(v.on) || std::isnan(v.off)) continue;
    s.values.push_back(v);
    s.lower_on += v.on < v.off ? 1 : 0;
    s.higher_on += v.on > v.off ? 1 : 0;
    s.min_on = std::min(s.min_on, v.on);
    s.max_on = std::max(s.max_on, v.on);
    s.min_off = std::min(s.min_off, v.off);
    s.max_off = std::max(s.max_off, v.off);
  }
  return s;
}

std::string range(double low, double high) {
  return report_number(low) == report_number(high) ? report_number(low)
                                                   : report_number(low) + "-" + report_number(high);
}

std::string ranges(const Spread& s) {
  return range(s.min_on, s.max_on) + " with compaction on against " + range(s.min_off, s.max_off) +
         " off";
}

std::string of_worlds(int count, int total) {
  return std::to_string(count) + " of " + std::to_string(total);
}

std::string spacing_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.member_spacing; });
  if (s.empty()) return "";
  return "Members of the final aggregates stand " + ranges(s) +
         " from their nearest fellow member (mean over the members, the range over the "
         "worlds with aggregates at the end): with compaction they close up to "
         "`controller.compaction.spacing` (2 r, touching), without it they stay about where "
         "they first perceived someone, up to s apart. ";
}

std::string growth_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.growth_vs_model; });
  if (s.empty()) return "";
  std::string text = "Searchers join aggregates at " + ranges(s) +
                     " times the rate the models' capture radius predicts (growths over "
                     "expected growths, every size pooled); growth is slower with compaction on "
                     "in " +
                     of_worlds(s.lower_on, s.count()) + " worlds that grow (median on / off " +
                     report_number(s.median_ratio()) + ")";
  text += 2 * s.lower_on > s.count()
              ? ": packed aggregates are smaller targets than the loose chains a searcher "
                "meets without compaction, closer to the packed discs the models assume. "
              : ": packing the aggregates does not make them smaller targets here. ";
  return text;
}

std::string escape_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.escape_fraction; });
  if (s.empty()) return "";
  std::string text = "Of the LEAVE attempts, " + ranges(s) +
                     " get out (escapes over attempts); fewer get out with compaction on in " +
                     of_worlds(s.lower_on, s.count()) + " worlds that leave (median on / off " +
                     report_number(s.median_ratio()) + ")";
  text += 2 * s.lower_on > s.count()
              ? ": an enclosed member is blocked by the bodies around it and rejoins, so "
                "aggregates lose members more slowly than the models' leave laws (every member, "
                "m p, or the periphery) say. "
              : ". ";
  return text;
}

std::string final_noa_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.final_noa; });
  if (s.empty()) return "";
  return "The final mean NOA is lower with compaction on in " + of_worlds(s.lower_on, s.count()) +
         " Bayindir worlds (median on / off " + report_number(s.median_ratio()) + "). ";
}

std::string error_sentence(const std::vector<CompactionEffect>& effects, bool bayindir) {
  const auto in_model = [bayindir](const CompactionEffect& e) { return e.bayindir == bayindir; };
  std::string parts;
  for (const std::string& variant :
       {std::string("original"), std::string(bayindir ? "collision" : "peripheral"),
        std::string(kMeasuredVariant)}) {
    const Spread s = spread_of(
        effects, [&](const CompactionEffect& e) { return e.error(variant); }, in_model);
    if (s.empty()) continue;
    parts += (parts.empty() ? "" : "; ") + variant + " in " + of_worlds(s.higher_on, s.count()) +
             " (median on / off " + report_number(s.median_ratio()) + ")";
  }
  if (parts.empty()) return "";
  return std::string(bayindir ? "Bayindir's NOA RMSE" : "Soysal's TV distance") +
         " is larger with compaction on for " + parts + ". ";
}

std::string claim_changes(const std::vector<ClaimCheck>& on, const std::vector<ClaimCheck>& off) {
  std::string text;
  for (std::size_t i = 0; i < on.size() && i < off.size(); ++i) {
    if (on[i].verdict == off[i].verdict) continue;
    text += "- **" + on[i].figures + "** " + on[i].claim + ": **" + on[i].verdict +
            "** with compaction on, **" + off[i].verdict + "** off. Off: " + off[i].evidence + "\n";
  }
  return text.empty() ? "No claim of the paper changes its verdict when compaction is off.\n"
                      : "Claims whose verdict changes when compaction is off:\n\n" + text;
}

}  // namespace

std::string compaction_section(const std::vector<CompactionEffect>& effects,
                               const std::vector<ClaimCheck>& claims_on,
                               const std::vector<ClaimCheck>& claims_off,
                               const std::string& off_folder) {
  std::string text = "## Compaction on and off\n\n";
  if (effects.empty()) {
    return text + "No Bayindir or Soysal world ran with compaction on, so nothing was compared.\n";
  }
  text +=
      "Everything above runs with compaction on (SPEC 3, the default: waiting agents close up "
      "to touching). Every Bayindir and Soysal experiment also ran with "
      "`controller.compaction.enabled=false` (runs and plots in `" +
      off_folder +
      "/`, `compaction.csv` holds every number below). Model errors, by the measure of each "
      "experiment's table above:\n\n" +
      error_table(effects) +
      "\nWhat compaction changes in the simulation (summary.json's final member spacing; "
      "rates.csv's growths (joins) over the growths the model's capture radius 2 rho_m v / A "
      "expects for the same exposure, and its escapes over LEAVE attempts):\n\n" +
      simulation_table(effects) + "\n";
  text += spacing_sentence(effects) + growth_sentence(effects) + escape_sentence(effects) +
          final_noa_sentence(effects) + error_sentence(effects, true) +
          error_sentence(effects, false) + "\n\n";
  return text + claim_changes(claims_on, claims_off);
}

}  // namespace swarmagg
