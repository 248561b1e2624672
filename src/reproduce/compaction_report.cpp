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
  int lower_on = 0;                    // worlds where the value is lower with compaction on
  int higher_on = 0;                   // and higher
  std::vector<std::string> unchanged;  // the worlds where it is the same both ways
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
    if (v.on == v.off) s.unchanged.push_back(e.world);
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

// "a-b with compaction on against c-d off" (ranges over the worlds).
std::string ranges(const Spread& s) {
  return range(s.min_on, s.max_on) + " with compaction on against " + range(s.min_off, s.max_off) +
         " off";
}

// "higher in 3, lower in 2 and unchanged in 1 (creation-50) of 6".
std::string split(const Spread& s, const std::string& higher, const std::string& lower) {
  std::string text = higher + " in " + std::to_string(s.higher_on) + ", " + lower + " in " +
                     std::to_string(s.lower_on);
  if (!s.unchanged.empty()) {
    text += " and unchanged in " + std::to_string(s.unchanged.size()) + " (";
    for (std::size_t i = 0; i < s.unchanged.size(); ++i) text += (i ? ", " : "") + s.unchanged[i];
    text += ")";
  }
  return text + " of " + std::to_string(s.count());
}

bool leaves(const CompactionEffect& e) {
  return !std::isnan(e.escape_fraction.on) || !std::isnan(e.escape_fraction.off);
}

std::string spacing_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.member_spacing; });
  if (s.empty()) return "";
  return "Members of the final aggregates stand " + ranges(s) +
         " from their nearest fellow member (mean over the members; ranges over the worlds with "
         "aggregates at the end): with compaction they close up to "
         "`controller.compaction.spacing` (2 r, touching), without it they stay about where "
         "they first perceived someone, up to s apart. ";
}

// Growth is compared where only searchers grow aggregates: where agents leave, a LEAVE attempt
// that does not get out rejoins its aggregate, and the measured growth counts that too.
std::string growth_sentence(const std::vector<CompactionEffect>& effects) {
  const auto quantity = [](const CompactionEffect& e) { return e.growth_vs_model; };
  const Spread s =
      spread_of(effects, quantity, [](const CompactionEffect& e) { return !leaves(e); });
  const Spread with_leaving = spread_of(effects, quantity, leaves);
  std::string text;
  if (!s.empty()) {
    text =
        "Where nobody leaves, growths over those the models' capture radius predicts for the "
        "same exposure (every size pooled) are " +
        ranges(s) + "; growth is " + split(s, "faster", "slower") +
        " such worlds with compaction on";
    text += 2 * s.lower_on > s.count()
                ? ": packed aggregates are smaller targets than the loose aggregates a searcher "
                  "meets without compaction, closer to the packed discs the models assume. "
                : ". ";
  }
  if (!with_leaving.empty()) {
    text +=
        "Where agents leave, failed LEAVE attempts rejoin and count as growths, so the "
        "ratio is " +
        split(with_leaving, "higher", "lower") + " such worlds with compaction on. ";
  }
  return text;
}

std::string escape_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.escape_fraction; });
  if (s.empty()) return "";
  std::string text = "Of the LEAVE attempts, " + ranges(s) + " get out (escapes over attempts), " +
                     split(s, "more", "fewer") +
                     " worlds that leave with compaction on (median on / off " +
                     report_number(s.median_ratio()) + ")";
  if (2 * s.lower_on <= s.count()) return text + ". ";
  // Where the attempts start: inside an aggregate (a member with 6 fellows around it, which
  // only aggregates of 7 or more have) or on its rim.
  const Spread inside =
      spread_of(effects, [](const CompactionEffect& e) { return e.inside_attempt_share; });
  text += ", so an aggregate loses fewer members than try to leave. ";
  if (inside.empty()) return text;
  text += "With compaction on, " + range(inside.min_on, inside.max_on) +
          " of the attempts start inside an aggregate (a member with 6 fellows around it, "
          "which only aggregates of 7 or more have), the rest on its rim. An attempt fails when "
          "its LEAVE phase ends with a member of the aggregate it left still within reach (the "
          "approach radius for Soysal's controller, the detection radius otherwise): the same "
          "leave walk (`leave_timeout` x v) gets out of reach of a compact aggregate less often "
          "than of a loose one. These runs do not tell apart how much of that is the walk's "
          "length against the reach and how much the walk bent by bodies in its way. ";
  return text;
}

std::string final_noa_sentence(const std::vector<CompactionEffect>& effects) {
  const Spread s = spread_of(effects, [](const CompactionEffect& e) { return e.final_noa; });
  if (s.empty()) return "";
  return "The final mean NOA is " + split(s, "higher", "lower") +
         " Bayindir worlds with compaction on. ";
}

std::string error_sentence(const std::vector<CompactionEffect>& effects, bool bayindir) {
  const auto in_model = [bayindir](const CompactionEffect& e) { return e.bayindir == bayindir; };
  std::string parts;
  for (const std::string& variant :
       {std::string("original"), std::string(bayindir ? "collision" : "peripheral"),
        std::string(kMeasuredVariant)}) {
    const auto error = [&](const CompactionEffect& e) { return e.error(variant); };
    const Spread s = spread_of(effects, error, in_model);
    if (s.empty()) continue;
    parts += (parts.empty() ? "" : "; ") + variant + " " + split(s, "larger", "smaller") +
             " (median on / off " + report_number(s.median_ratio()) + ")";
  }
  if (parts.empty()) return "";
  // The world whose original-variant error moved most, and what moved with it.
  const CompactionEffect* most = nullptr;
  double largest = 0.0;
  for (const CompactionEffect& e : effects) {
    const OnOff v = e.error("original");
    const double change = std::abs(v.on - v.off);
    if (in_model(e) && std::isfinite(change) && change > largest) {
      most = &e;
      largest = change;
    }
  }
  std::string text = std::string(bayindir ? "Bayindir's NOA RMSE" : "Soysal's TV distance") +
                     " with compaction on, by variant: " + parts + ".";
  if (most) {
    text += " The original variant moved most in " + most->world + " (" +
            report_number(most->error("original").off) + " off, " +
            report_number(most->error("original").on) + " on)";
    if (leaves(*most)) {
      text += ", where " + report_number(most->escape_fraction.on) +
              " of the LEAVE attempts get out with compaction on against " +
              report_number(most->escape_fraction.off) + " off";
    }
    if (!std::isnan(most->final_noa.on)) {
      text += (leaves(*most) ? " and" : ", where") + std::string(" the final mean NOA is ") +
              report_number(most->final_noa.on) + " against " + report_number(most->final_noa.off);
    }
    text += ".";
  }
  return text + " ";
}

std::string claim_changes(const std::vector<ClaimCheck>& on, const std::vector<ClaimCheck>& off) {
  std::string text;
  for (std::size_t i = 0; i < on.size() && i < off.size(); ++i) {
    if (on[i].verdict == off[i].verdict) continue;
    text += "- **" + on[i].figures + "** " + on[i].claim + ": **" + on[i].verdict +
            "** with compaction on, **" + off[i].verdict + "** off. Off: " + off[i].evidence + "\n";
  }
  if (!text.empty()) return "Claims whose verdict changes when compaction is off:\n\n" + text;
  const bool any_checked = std::any_of(
      on.begin(), on.end(), [](const ClaimCheck& claim) { return claim.verdict != "not checked"; });
  return any_checked ? "No claim of the paper changes its verdict when compaction is off.\n"
                     : "No claim of the paper was checked (the worlds run do not cover one).\n";
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
      "Everything above runs with compaction on (docs/controllers.md, the default: waiting agents "
      "close up "
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
