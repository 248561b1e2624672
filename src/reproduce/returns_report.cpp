#include "reproduce/returns_report.hpp"

#include <algorithm>

#include "analysis/replicate_spread.hpp"
#include "analysis/variant_error.hpp"
#include "models/return_probability.hpp"
#include "reproduce/report.hpp"

namespace swarmagg {

namespace {

std::string ratio_text(const VariantError& e) {
  if (!e.noise_floor || *e.noise_floor <= 0.0) return "-";
  return report_number(e.error / *e.noise_floor) + "x";
}

std::string floor_text(const VariantError& e) {
  return e.noise_floor ? report_number(*e.noise_floor) : "-";
}

std::string errors_cell(const std::vector<VariantError>& errors) {
  std::string text;
  for (const VariantError& e : errors) {
    text += (text.empty() ? "" : "<br>") + e.variant + " " + report_number(e.error) + " / " +
            floor_text(e) + " (" + ratio_text(e) + ")";
  }
  return text;
}

std::string distribution_text(const std::map<int, double>& distribution) {
  std::string text;
  for (const auto& [value, fraction] : distribution) {
    if (fraction < 0.005) continue;
    text += (text.empty() ? "" : ", ") + std::to_string(value) + ": " + report_number(fraction);
  }
  return text.empty() ? "-" : text;
}

std::string trend_text(const NoaTrend& trend) {
  // A second half of fewer than two recorded steps has no slope: neither stationary nor not.
  if (trend.replicates == 0) return "not judged (fewer than 2 recorded steps in the second half)";
  return report_number(trend.change) + " [" + report_number(trend.low) + ", " +
         report_number(trend.high) + "] " +
         (!trend.stationary() ? "**trending**"
          : trend.replicates > 0 && trend.frozen == trend.replicates
              ? "NOA fixed (every replicate's NOA constant)"
          : trend.frozen > 0 ? "stationary, NOA constant in " + std::to_string(trend.frozen) +
                                   " of " + std::to_string(trend.replicates) + " replicates"
                             : "stationary");
}

// "12.83x its floor (misses)", with "; 4.7x the replicates' spread" where that spread exceeds
// the variant's floor: the floor then understates the simulation's own noise.
std::string ratio_words(const std::vector<VariantError>& errors, const std::string& name,
                        double spread) {
  const std::optional<double> ratio = ratio_of(errors, name);
  if (!ratio) return "has no floor";
  std::string text =
      report_number(*ratio) + "x its floor (" + (*ratio <= kFitsWithin ? "fits" : "misses");
  const VariantError* e = find_error(errors, name);
  if (spread > *e->noise_floor)
    text += "; " + report_number(e->error / spread) + "x the replicates' spread";
  return text + ")";
}

// The paper's variant nearest its noise floor (error / floor), which need not be the one of
// lowest error (the claims compare errors): the floors differ between variants.
std::string best_paper_variant(const std::vector<VariantError>& errors) {
  const VariantError* best = nullptr;
  for (const VariantError& e : errors) {
    if (e.variant == kMeasuredVariant || e.variant == kReturnsVariant || !e.noise_floor) continue;
    if (!best || e.error / *e.noise_floor < best->error / *best->noise_floor) best = &e;
  }
  return best ? best->variant : "original";
}

std::string returns_text(const ReturnSummary& returns) {
  return std::to_string(returns.returns) + " / " + std::to_string(returns.attempts) + " (" +
         report_number(returns.fraction()) + ")";
}

// Fewer than 10 returns of a size are not timed (rates' rule): "-" when none was, and the
// share timed when it is not all of them, so that the mean is not read as every return's.
std::string time_text(const ReturnSummary& returns) {
  if (returns.timed == 0) return "-";
  std::string text = report_number(returns.mean_time) + " tu";
  if (returns.timed < returns.returns)
    text += ", over " + std::to_string(returns.timed) + " of " + std::to_string(returns.returns) +
            " returns";
  return text;
}

std::string timeout_label(const TimeoutPoint& p) {
  return p.world + " at timeout " + report_number(p.leave_timeout);
}

// What the numbers say is left once returns are accounted for: the experiments where the
// measured variant (measured q, new joins) still misses, and whether any run was trending.
std::string remaining_miss(const std::vector<FigureResult>& results,
                           const std::vector<TimeoutPoint>& series) {
  std::vector<std::string> misses;
  int judged = 0;
  bool trending = false;
  const auto judge = [&](const std::string& label, const std::vector<VariantError>& errors) {
    const std::optional<double> ratio = ratio_of(errors, kMeasuredVariant);
    if (!ratio) return;
    ++judged;
    if (*ratio > kFitsWithin) misses.push_back(label + " (" + report_number(*ratio) + "x)");
  };
  for (const FigureResult& r : results) {
    if (const std::vector<VariantError>* errors = model_errors(r))
      judge(r.worlds.front().name, *errors);
    trending |= r.trend && !r.trend->stationary();
  }
  // The series' point at the worlds' own timeout is its figure's run, judged above already
  // when its figure was reproduced (not with --only timeout-series).
  const auto figure_judged = [&results](const std::string& world) {
    return std::any_of(results.begin(), results.end(), [&world](const FigureResult& r) {
      return model_errors(r) && r.worlds.front().name == world;
    });
  };
  for (const TimeoutPoint& p : series) {
    if (!p.paper_run || !figure_judged(p.world)) judge(timeout_label(p), p.comparison.errors);
    trending |= !p.trend.stationary();
  }
  std::string text = "\nWith returns accounted for, the `measured` variant is within " +
                     report_number(kFitsWithin) + "x its noise floor in " +
                     std::to_string(judged - static_cast<int>(misses.size())) + " of " +
                     std::to_string(judged) + " comparisons";
  if (misses.empty()) {
    text +=
        ": what the paper's variants miss beyond their floor is the returns they count as "
        "departures, and the terms the measured variant replaces.";
  } else {
    text += "; it still misses in";
    for (std::size_t k = 0; k < misses.size(); ++k) text += (k ? ", " : " ") + misses[k];
    text +=
        ", where the model's structure (any free agent may join any aggregate; searchers "
        "that keep their heading on the torus) is what remains.";
  }
  if (trending) {
    text +=
        " Some runs were still trending over their second half (see above): their run "
        "average is not the stationary one the comparison assumes.";
  }
  return text + "\n\n";
}

}  // namespace

ReturnSummary pooled_returns(const std::vector<RateRow>& rates, int smallest) {
  ReturnSummary summary;
  double time_sum = 0.0;
  for (const RateRow& row : rates) {
    if (!row.size || *row.size < smallest) continue;
    if (row.term == "return") {
      summary.attempts += static_cast<std::uint64_t>(row.estimate.exposure);
      summary.returns += row.estimate.events;
    } else if (row.term == "return_time" && row.estimate.rate) {
      time_sum += *row.estimate.rate * static_cast<double>(row.estimate.events);
      summary.timed += row.estimate.events;
    }
  }
  if (summary.timed) summary.mean_time = time_sum / static_cast<double>(summary.timed);
  return summary;
}

double returning_share_of_joins(const std::vector<RateRow>& rates) {
  double joins = 0.0, fresh = 0.0;
  for (const RateRow& row : rates) {
    if (row.term == "join" || row.term == "growth")
      joins += static_cast<double>(row.estimate.events);
    if (row.term == "join_new") fresh += static_cast<double>(row.estimate.events);
  }
  return joins > 0.0 ? 1.0 - fresh / joins : 0.0;
}

std::string noise_floor_section(const std::vector<FigureResult>& results,
                                const std::vector<TimeoutPoint>& series) {
  std::string text =
      "## Every model error beside its noise floor\n\nThe noise floor is the error a variant "
      "shows against its own process (Soysal: the partition chain run as a Markov process; "
      "Bayindir: the stochastic model) simulated with the same replicates and run length, "
      "mean of 20 batches (`model.csv`, `summary.json`'s `model_errors`). Each cell: variant, "
      "error / floor (ratio). A variant fits when its error is within " +
      report_number(kFitsWithin) +
      "x its floor. The replicates' spread is the simulation's own noise by the same metric: "
      "how far the replicates' mean curve (or partition distribution) falls, on average, from "
      "that of " +
      std::to_string(kSpreadResamples) +
      " bootstrap resamples of them. Where it exceeds a floor (replicates that settle at "
      "different values, which the model's process, mixing, does not), the floor understates "
      "the noise, and the text below gives the error as a multiple of the spread too.\n\n"
      "| Fig | world | metric | errors / noise floors | replicates' spread |\n"
      "|---|---|---|---|---|\n";
  for (const FigureResult& r : results) {
    const std::vector<VariantError>* errors = model_errors(r);
    if (!errors) continue;
    text += "| " + r.figure.figures + " | " + r.worlds.front().name + " | " +
            (r.noa ? "rmse_noa" : "tv_partition") + " | " + errors_cell(*errors) + " | " +
            report_number(replicates_spread(r)) + " |\n";
  }
  for (const TimeoutPoint& p : series) {
    text += "| timeout series | " + timeout_label(p) + " | tv_partition | " +
            errors_cell(p.comparison.errors) + " | " + report_number(p.comparison.spread) + " |\n";
  }
  return text + "\n";
}

std::string soysal_distribution_section(const std::vector<FigureResult>& results) {
  std::string text =
      "## Soysal runs: NOA, largest aggregate, stationarity\n\nFraction of the recorded steps "
      "(all replicates) at each NOA and each largest-aggregate size (values under 0.005 left "
      "out), and the NOA change over the second half of the run (mean of the replicates' "
      "least-squares slopes times the half's length, 95% t interval): stationary when the "
      "interval holds 0. The partition comparison assumes a stationary run where the run "
      "average is dominated by the late part. NOA fixed: every replicate's NOA is constant over "
      "the second half, so no trend shows, but the number of aggregates does not mix either "
      "(members may still move between aggregates); which number each replicate settled at is "
      "then chance, and the noise floor (the chain's own noise, which mixes) understates how "
      "far another set of replicates could fall from this one.\n\n| "
      "Fig | world | NOA | largest aggregate | NOA "
      "change over the second half |\n|---|---|---|---|---|\n";
  for (const FigureResult& r : results) {
    if (!r.partitions || !r.trend) continue;
    text += "| " + r.figure.figures + " | " + r.worlds.front().name + " | " +
            distribution_text(r.noa_distribution) + " | " +
            distribution_text(r.largest_distribution) + " | " + trend_text(*r.trend) + " |\n";
  }
  return text + "\n";
}

std::string timeout_series_section(const std::vector<TimeoutPoint>& series) {
  if (series.empty()) return "";
  std::string text =
      "## The leave-timeout series\n\nThe 10- and 20-agent Soysal worlds with leave_timeout "
      "10, 20, 30 and 50 tu (approach radius 12, speed 1; runs in `timeout-series/runs/`, "
      "numbers in `timeout-series.csv`). Returns: LEAVE attempts from aggregates of 3 or more "
      "that came back; q predicted: the `returns` variant's q(5).\n\n| world | timeout | tu x "
      "replicates | returns (measured) | mean return time | q(5) predicted | TV / floor: "
      "original, peripheral, returns, measured | NOA change over 2nd half | simulation s |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const TimeoutPoint& p : series) {
    const ReturnSummary returns = pooled_returns(p.rates);
    std::string ratios;
    for (const char* name : {"original", "peripheral", kReturnsVariant, kMeasuredVariant}) {
      const std::optional<double> ratio = ratio_of(p.comparison.errors, name);
      const VariantError* e = find_error(p.comparison.errors, name);
      ratios += std::string(ratios.empty() ? "" : ", ") + (e ? report_number(e->error) : "-") +
                " (" + (ratio ? report_number(*ratio) + "x" : "-") + ")";
    }
    const RateRow* predicted = nullptr;
    for (const RateRow& row : p.rates) {
      if (row.term == "return" && row.size == 5 && !row.models.empty()) predicted = &row;
    }
    text += "| " + p.world + " | " + report_number(p.leave_timeout) + " | " +
            report_number(p.duration) + " x " + std::to_string(p.replicates) + " | " +
            returns_text(returns) + " | " + time_text(returns) + " | " +
            (predicted ? report_number(predicted->models.front().rate) : "-") + " | " + ratios +
            " | " + trend_text(p.trend) + " | " + report_number(p.simulation_seconds) + " |\n";
  }
  return text + "\n![Error against the leave timeout](plots/timeout-series.png)\n\n";
}

std::string why_models_miss_section(const std::vector<FigureResult>& results,
                                    const std::vector<TimeoutPoint>& series) {
  std::string text =
      "## Why the models miss\n\nBoth models treat a leaver as a fresh searcher. Each run "
      "follows every LEAVE attempt (`rates.csv`, terms `return`, `return_time`, `join_new`; "
      "docs/models-returns.md) and counts a return when the leaver's next WAIT is in an "
      "aggregate holding a member of the one it left who kept waiting all the while (one who "
      "searched again in between is in a new aggregate), within 3 leave timeouts. The numbers "
      "below are this run's.\n\n";
  for (const FigureResult& r : results) {
    const std::vector<VariantError>* errors = model_errors(r);
    if (!errors || r.rates.empty()) continue;
    const WorldSpec& w = r.worlds.front();
    if (!w.controller.leave) continue;
    const ReturnSummary returns = pooled_returns(r.rates);
    const std::string best = best_paper_variant(*errors);
    text += "- **" + w.name + "** (Fig " + r.figure.figures + "): ";
    if (returns.attempts == 0) {
      const ReturnSummary pairs = pooled_returns(r.rates, 2);
      text += pairs.attempts == 0
                  ? "no agent tried to leave, so none came back. "
                  : "only pairs left (" + returns_text(pairs) + " of their leavers came back). ";
    } else {
      text += returns_text(returns) +
              " LEAVE attempts from aggregates of 3 or more came back (mean time away " +
              time_text(returns) + "); returns were " +
              report_number(100.0 * returning_share_of_joins(r.rates)) + " % of all joins. ";
    }
    const double spread = replicates_spread(r);
    text +=
        "Of the variants without returns, the one nearest its noise floor (" + best + ") is at " +
        ratio_words(*errors, best, spread) + "; `returns` (q from the parameters) at " +
        ratio_words(*errors, kReturnsVariant, spread) + "; `measured` (measured q, new joins) at " +
        ratio_words(*errors, kMeasuredVariant, spread) + ".";
    if (r.trend && !r.trend->stationary())
      text +=
          " The run was still trending over its second half, so no variant can be judged "
          "on it alone.";
    text += "\n";
  }
  if (!series.empty()) {
    text +=
        "\nThe leave-timeout series separates the effects. Where `leave_timeout x v` is shorter "
        "than the approach radius the leaver still perceives its aggregate when the timeout "
        "ends, so the paper's L(i) counts excursions, not departures:\n\n";
    for (const TimeoutPoint& p : series) {
      const ReturnSummary returns = pooled_returns(p.rates);
      const std::vector<VariantError>& errors = p.comparison.errors;
      const double spread = p.comparison.spread;
      text += "- " + timeout_label(p) + ": " + returns_text(returns) + " return; peripheral " +
              ratio_words(errors, "peripheral", spread) + ", returns " +
              ratio_words(errors, kReturnsVariant, spread) + ", measured " +
              ratio_words(errors, kMeasuredVariant, spread) +
              (p.trend.stationary() ? "" : "; NOA still trending") + ".\n";
    }
  }
  text += remaining_miss(results, series);
  return text;
}

}  // namespace swarmagg
