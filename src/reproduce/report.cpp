#include "reproduce/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "controllers/controller_registry.hpp"
#include "models/aggregate_shape.hpp"
#include "rates/geometry_fits.hpp"
#include "reproduce/paper_predictions.hpp"
#include "reproduce/returns_report.hpp"

namespace swarmagg {
namespace {

// The variant of lowest error (the measured variant is judged in its own section), and the
// runner-up when the two differ by less than the larger of their noise floors: a difference
// the simulation's own noise makes is no ranking.
std::string best_of(const std::vector<VariantError>& errors) {
  const VariantError* best = nullptr;
  const VariantError* second = nullptr;
  for (const VariantError& e : errors) {
    if (e.variant == kMeasuredVariant) continue;
    if (!best || e.error < best->error) {
      second = best;
      best = &e;
    } else if (!second || e.error < second->error) {
      second = &e;
    }
  }
  if (!best) return "-";
  if (!second || !best->noise_floor || !second->noise_floor) return best->variant;
  const double noise = std::max(*best->noise_floor, *second->noise_floor);
  if (second->error - best->error >= noise) return best->variant;
  return best->variant + " (within noise of " + second->variant + ")";
}

std::string most_likely(const Distribution& d) {
  const std::pair<const std::string, double>* best = nullptr;
  for (const auto& entry : d) {
    if (!best || entry.second > best->second) best = &entry;
  }
  return best ? best->first + " (" + report_number(best->second) + ")" : "-";
}

// The row's link to its figure, and the figures themselves under each table, so the report
// reads on its own in any Markdown viewer.
std::string plot_link(const FigureResult& r) {
  return "[Fig " + r.figure.figures + "](" + r.plot + ")";
}

std::string figure_images(const std::vector<FigureResult>& results,
                          bool (*shown)(const FigureResult&)) {
  std::string text;
  for (const FigureResult& r : results) {
    if (!shown(r) || r.plot.empty()) continue;
    text += "### Fig " + r.figure.figures + ": " + r.figure.title + "\n\n![Fig " +
            r.figure.figures + ": " + r.figure.title + "](" + r.plot + ")\n\n";
  }
  return text;
}

bool is_encounter_figure(const FigureResult& r) {
  return !r.encounters.empty();
}
bool is_noa_figure(const FigureResult& r) {
  return r.noa.has_value();
}
bool is_partition_figure(const FigureResult& r) {
  return r.partitions.has_value();
}

std::string encounter_table(const std::vector<FigureResult>& results) {
  std::string text =
      "| Fig | world | N | v | simulated encounters/tu (mean ± sd) | kinetic theory | deviation | "
      "paper fit | deviation | plot |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FigureResult& r : results) {
    for (std::size_t i = 0; i < r.encounters.size(); ++i) {
      const EncounterPoint& p = r.encounters[i];
      text += "| " + r.figure.figures + " | " + r.figure.worlds[i] + " | " +
              std::to_string(p.agents) + " | " + report_number(p.speed) + " | " +
              report_number(p.simulated) + " ± " + report_number(p.simulated_sd) + " | " +
              report_number(p.kinetic) + " | " +
              report_number(100 * (p.simulated - p.kinetic) / p.kinetic) + " % | " +
              report_number(p.paper_fit) + " | " +
              report_number(100 * (p.simulated - p.paper_fit) / p.paper_fit) + " % | " +
              plot_link(r) + " |\n";
    }
  }
  return text;
}

std::string noa_table(const std::vector<FigureResult>& results) {
  std::string text =
      "| Fig | world | N | p | final mean NOA | RMSE original | RMSE collision (kinetic) | RMSE "
      "collision-paper "
      "| best | paper's improved vs original | plot "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FigureResult& r : results) {
    if (!r.noa) continue;
    const WorldSpec& w = r.worlds.front();
    const auto& errors = r.noa->errors;
    const NoaSeries& sim = r.noa->simulation;
    const bool improved =
        variant_error(errors, kPaperFitVariant) < variant_error(errors, "original");
    text += "| " + r.figure.figures + " | " + w.name + " | " + std::to_string(w.robots.count) +
            " | " + report_number(w.controller.leave ? w.controller.p_leave : 0.0) + " | " +
            report_number(sim.mean_at(sim.steps.size() - 1)) + " | " +
            report_number(variant_error(errors, "original")) + " | " +
            report_number(variant_error(errors, "collision")) + " | " +
            report_number(variant_error(errors, kPaperFitVariant)) + " | " + best_of(errors) +
            " | " + (improved ? "improved" : "original") + " | " + plot_link(r) + " |\n";
  }
  return text;
}

std::string partition_table(const std::vector<FigureResult>& results) {
  std::string text =
      "| Fig | world | N | TV original | TV peripheral | better | most likely: simulation | model "
      "original | "
      "model peripheral | plot |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FigureResult& r : results) {
    if (!r.partitions) continue;
    const WorldSpec& w = r.worlds.front();
    const PartitionComparison& c = *r.partitions;
    text += "| " + r.figure.figures + " | " + w.name + " | " + std::to_string(w.robots.count) +
            " | " + report_number(variant_error(c.errors, "original")) + " | " +
            report_number(variant_error(c.errors, "peripheral")) + " | " + best_of(c.errors) +
            " | " + most_likely(c.simulation) + " | " + most_likely(c.models[0]) + " | " +
            most_likely(c.models[1]) + " | " + plot_link(r) + " |\n";
  }
  return text;
}

// The chosen variant's value of a term (the variant model.creation / model.leaving names),
// else the first variant's.
const ModelTerm* chosen_term(const WorldSpec& world, const RateRow& row) {
  const std::string chosen =
      controller_rules(world).model == ModelFamily::Soysal
          ? (world.model.leaving == LeavingVariant::Original ? "original" : "peripheral")
          : (world.model.creation == CreationVariant::Original ? "original" : "collision");
  for (const ModelTerm& m : row.models) {
    if (m.variant == chosen) return &m;
  }
  return row.models.empty() ? nullptr : &row.models.front();
}

// The measured rate furthest from the world's model variant: first by how far its interval
// lies from 1 (0 when it holds 1: a wide interval proves nothing), then by |log ratio|.
// Returns are no term of the paper's variants (their own section weighs them). The
// geometry (radius, rim) is a shape, not a rate: the models feel it only through the growth
// and escape rates measured here, and it has a table of its own.
std::string most_deviant_term(const WorldSpec& world, const std::vector<RateRow>& rows) {
  // Where returns are measured apart, joins that are not returns (join_new) are the term the
  // models' growth means; every join (growth, join) counts the returns too.
  const bool new_joins_apart = std::any_of(
      rows.begin(), rows.end(), [](const RateRow& row) { return row.term == "join_new"; });
  const RateRow* worst = nullptr;
  std::pair<double, double> worst_distance{-1.0, -1.0};
  double ratio = 0.0;
  const ModelTerm* worst_model = nullptr;
  for (const RateRow& row : rows) {
    if (row.term == "radius" || row.term == "rim" || row.term == "return") continue;
    if (new_joins_apart && (row.term == "growth" || row.term == "join")) continue;
    const ModelTerm* model = chosen_term(world, row);
    if (!row.estimate.rate || !model || model->rate <= 0.0) continue;
    const double r = *row.estimate.rate / model->rate;
    const double outside = std::max({0.0, std::log(*row.estimate.low / model->rate),
                                     std::log(model->rate / *row.estimate.high)});
    const std::pair<double, double> distance{outside, std::abs(std::log(r))};
    if (distance > worst_distance) {
      worst = &row;
      worst_distance = distance;
      ratio = r;
      worst_model = model;
    }
  }
  if (!worst) return "- | -";
  // Every interval holds the model's value: the largest ratio would be noise, not a finding.
  if (worst_distance.first <= 0.0) return "none outside its 95% CI | -";
  return worst->term + (worst->size ? " " + std::to_string(*worst->size) : "") + " | " +
         report_number(ratio) + " [" + report_number(*worst->estimate.low / worst_model->rate) +
         ", " + report_number(*worst->estimate.high / worst_model->rate) + "]";
}

// No miss to explain where a paper variant fits (within kFitsWithin of its noise floor).
// Else, where the measured variant closes most of the gap, the paper's terms were wrong;
// where it misses as much, the structure (mean field, Markov chain over partitions) is.
std::string reading(const std::vector<VariantError>& errors, const std::string& second) {
  for (const char* name : {"original", second.c_str()}) {
    const std::optional<double> ratio = ratio_of(errors, name);
    if (ratio && *ratio <= kFitsWithin)
      return "no miss: " + std::string(name) + " is within " + report_number(kFitsWithin) +
             "x its noise floor";
  }
  const double best_paper =
      std::min(variant_error(errors, "original"), variant_error(errors, second));
  const double measured = variant_error(errors, kMeasuredVariant);
  if (measured <= 0.5 * best_paper) return "the terms: measured terms fix most of the error";
  if (measured < best_paper) return "partly the terms; the rest is the model's structure";
  return "the model's structure: measured terms do not help";
}

std::string why_table(const std::vector<FigureResult>& results) {
  std::string text =
      "| Fig | world | most deviant term | measured / model [95% CI] | error original | error "
      "collision / peripheral | error measured | where the miss comes from |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (const FigureResult& r : results) {
    const std::vector<VariantError>* errors = r.noa          ? &r.noa->errors
                                              : r.partitions ? &r.partitions->errors
                                                             : nullptr;
    if (!errors || r.rates.empty()) continue;
    const WorldSpec& w = r.worlds.front();
    const std::string second = r.noa ? "collision" : "peripheral";
    const double original = variant_error(*errors, "original");
    const double other = variant_error(*errors, second);
    const double measured = variant_error(*errors, kMeasuredVariant);
    text += "| " + r.figure.figures + " | " + w.name + " | " + most_deviant_term(w, r.rates) +
            " | " + report_number(original) + " | " + report_number(other) + " | " +
            report_number(measured) + " | " + reading(*errors, second) + " |\n";
  }
  return text;
}

std::string fitted_text(const PowerLawFit& fit) {
  if (!fit.fitted()) return "- | -";
  auto parameter = [](const FittedParameter& p, double paper) {
    return report_number(p.value) + " [" + report_number(p.low) + ", " + report_number(p.high) +
           "]" + (p.covers(paper) ? "" : " ✗");
  };
  return parameter(*fit.a, kPaperPackingScale) + " | " + parameter(*fit.b, kPaperPackingExponent);
}

// The measured rim share rim / m of the largest size with a measured rim: 1 when no member
// of an aggregate that large is interior (a compact pack's share falls as m^-1/2).
std::string largest_rim_share(const std::vector<RateRow>& rows) {
  const RateRow* largest = nullptr;
  for (const RateRow& row : rows) {
    if (row.term == "rim" && row.size && row.estimate.rate) largest = &row;
  }
  if (!largest) return "-";
  return report_number(*largest->estimate.rate / *largest->size) +
         " (m = " + std::to_string(*largest->size) + ")";
}

// The aggregate geometry laws fitted on each experiment whose aggregates come in enough
// sizes (worlds without joining form pairs only).
std::string geometry_table(const std::vector<FigureResult>& results) {
  std::string text =
      "| Fig | world | sizes | R1 law a [95% CI] | R1 law b | rim law a | rim law b | rim / m at "
      "the largest size |\n"
      "|---|---|---|---|---|---|---|---|\n";
  bool any = false;
  for (const FigureResult& r : results) {
    if (r.rates.empty()) continue;
    const WorldSpec& w = r.worlds.front();
    const GeometryFits fits = fit_geometry_laws(r.rates, w.robots.radius);
    if (!fits.radius.fitted() && !fits.rim.fitted()) continue;
    any = true;
    text += "| " + r.figure.figures + " | " + w.name + " | " + std::to_string(fits.radius.sizes) +
            " | " + fitted_text(fits.radius) + " | " + fitted_text(fits.rim) + " | " +
            largest_rim_share(r.rates) + " |\n";
  }
  return any ? text : "No experiment formed aggregates of enough sizes to fit the laws.\n";
}

std::string claim_lines(const std::vector<ClaimCheck>& claims) {
  std::string text;
  for (const ClaimCheck& c : claims) {
    text += "- **" + c.figures + "** " + c.claim + ": **" + c.verdict + "**. " + c.evidence + "\n";
  }
  return text;
}

}  // namespace

std::string report_number(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

std::string report_markdown(const ReportContext& context, const std::vector<FigureResult>& results,
                            const std::vector<ClaimCheck>& claims) {
  std::string text = "# Reproduction of the paper's experiments\n\n";
  text +=
      "Generated by `swarmagg reproduce` (" + context.mode + ", engine " + context.engine + ", " +
      report_number(context.wall_seconds) +
      " s). Plots are in `plots/` (each `.gp` beside the CSVs it reads); runs and model outputs in "
      "`runs/<world>/`.\n\n"
      "Model variants: Bayindir `original` (creation sqrt 2 s v dt y^2 / A), `collision` (kinetic "
      "theory, "
      "(4/pi) s v dt y(y-1) / A, docs/models.md), `collision-paper` (the paper's improved model "
      "with its "
      "fitted "
      "constant, C s v y^2 dt; it has no area term, so a constant fitted on one arena cannot hold "
      "on "
      "another: see the deviation columns of Figs 7-8); Soysal `original` (every member may leave) "
      "and `peripheral` "
      "(uncapped "
      "periphery, `periphery_cap: false`, as the paper's 5-agent improvement needs); for worlds "
      "whose aggregates lose agents, `returns` (the world's variant losing only leavers that do "
      "not come back, q(i) predicted from the world's parameters; docs/models.md); and "
      "`measured` (the same equations fed with the run's measured terms: new joins, and leave "
      "attempts times the fraction that does not return).\n\n";
  text += "## Collision theory (Figs 7-8)\n\n" + encounter_table(results) + "\n" +
          figure_images(results, is_encounter_figure);
  text +=
      "## Bayindir NOA (Figs 9-19)\n\nError: RMSE over the recorded steps between the simulation's "
      "mean NOA "
      "across replicates and the variant's expected NOA.\n\n" +
      noa_table(results) + "\n" + figure_images(results, is_noa_figure);
  text +=
      "## Soysal partitions (Figs 20-29)\n\nError: total-variation distance between the "
      "simulation's mean "
      "time fraction per partition and the model's partition probabilities averaged over the same "
      "run "
      "length (transient included, as the simulation's fractions are).\n\n" +
      partition_table(results) + "\n" + figure_images(results, is_partition_figure);
  text += noise_floor_section(results, context.timeout_series) +
          soysal_distribution_section(results) + timeout_series_section(context.timeout_series) +
          why_models_miss_section(results, context.timeout_series);
  text +=
      "### The measured terms\n\nEach run measures the terms the models are built from "
      "(`runs/<world>/rates.csv`, exact Poisson 95% intervals, terms with fewer than 10 "
      "events left out). The table gives the term furthest from the world's model variant "
      "(ratio measured / model), and the error (NOA RMSE or TV distance, as above) of the paper's "
      "variants beside that of the `measured` variant: the same equations fed with the measured "
      "creation (pair-up) and new-join rates, started like every variant from the state after "
      "the first decision (`model.initial_state`), and losing agents at the measured LEAVE "
      "attempt rate times the fraction that does not return. "
      "The aggregates' mean outer radius (`radius`) and rim count (`rim`) by size, observed at "
      "the recorded steps (95% intervals with each replicate one cluster), are in rates.csv too "
      "but not in this column: the models feel them only through the growth and escape rates, "
      "and the fits below sum them up.\n\n" +
      why_table(results) +
      "\nThe laws the models take from the paper's Fig 6, R1 = r a m^b and periph(m) = pi (a m^b "
      "- 1) with a = 1.20, b = 0.48, fitted to the measured mean radius and rim count by weighted "
      "least squares in log-log (weights: observations per size; sizes with fewer than 10 "
      "observations, or seen in one replicate only, left out; 95% intervals from the regression's "
      "standard errors; ✗: the paper's value lies outside). Worlds without joining form pairs "
      "only and have no fit. The paper's law describes compact packs (R1 ~ m^0.5, a rim share "
      "falling with m); b well above 0.5 and a rim share of 1 (no member with 6 fellows within "
      "1.2 x spacing) at sizes of 7 or more mean branched aggregates (below 7 no member can "
      "have 6 fellows, packed or not), and then a rim fit near 0.48 only restates "
      "rim = m over few sizes.\n\n" +
      geometry_table(results) + "\n";
  text += "## Claims of the paper\n\n" + claim_lines(claims);
  return text;
}

}  // namespace swarmagg
