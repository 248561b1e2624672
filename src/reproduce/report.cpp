#include "reproduce/report.hpp"

#include <cstdio>

#include "reproduce/paper_predictions.hpp"

namespace swarmagg {
namespace {

std::string best_of(const std::vector<VariantError>& errors) {
  const VariantError* best = &errors.front();
  for (const VariantError& e : errors) {
    if (e.error < best->error) best = &e;
  }
  return best->variant;
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
      "| best | paper's improved vs original | plot |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
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
      "(4/pi) s v dt y(y-1) / A, SPEC 5.1), `collision-paper` (the paper's improved model with its "
      "fitted "
      "constant, C s v y^2 dt; it has no area term, so a constant fitted on one arena cannot hold "
      "on "
      "another: see the deviation columns of Figs 7-8); Soysal `original` (every member may leave) "
      "and `peripheral` "
      "(uncapped "
      "periphery, `periphery_cap: false`, as the paper's 5-agent improvement needs; SPEC 5.3).\n\n";
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
  text += "## Claims of the paper\n\n" + claim_lines(claims);
  return text;
}

}  // namespace swarmagg
