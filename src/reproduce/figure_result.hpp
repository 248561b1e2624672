#pragma once
// What reproduce measured for one paper figure: the worlds it ran (or reused) and the
// comparison of their outputs with the models, filled according to the figure's kind.
#include <map>
#include <optional>
#include <vector>

#include "analysis/partition_comparison.hpp"
#include "analysis/run_stationarity.hpp"
#include "config/world_spec.hpp"
#include "rates/rate_rows.hpp"
#include "reproduce/encounter_comparison.hpp"
#include "reproduce/noa_comparison.hpp"
#include "reproduce/paper_figures.hpp"
#include "reproduce/run_summary_facts.hpp"

namespace swarmagg {

struct FigureResult {
  PaperFigure figure;
  std::vector<WorldSpec> worlds;                  // as run, in figure.worlds order
  std::vector<EncounterPoint> encounters;         // EncountersVsCount / EncountersVsSpeed
  std::optional<NoaComparison> noa;               // Noa
  std::optional<PartitionComparison> partitions;  // Partition
  std::vector<RateRow> rates;                     // Noa / Partition: the run's measured terms
  RunSummaryFacts summary;                        // Noa / Partition: summary.json's, pooled
  // Partition: the NOA trend over the second half (stationarity) and the distributions of
  // NOA and of the largest aggregate over every recorded step (analysis/run_stationarity).
  std::optional<NoaTrend> trend;
  std::map<int, double> noa_distribution, largest_distribution;
  std::string plot;  // the figure's PNG, relative to the report's folder ("plots/<id>.png")
  int reused = 0;    // worlds whose run folder was reused
  double wall_seconds = 0.0;
};

// The errors per model variant of its NOA or partition comparison; nullptr for a figure
// with neither.
const std::vector<VariantError>* model_errors(const FigureResult& result);
// The replicates' own spread by the same metric (analysis/replicate_spread.hpp); 0 for a
// figure without a model comparison.
double replicates_spread(const FigureResult& result);

// The error of `variant` in a NOA or partition comparison (throws when absent).
double variant_error(const std::vector<VariantError>& errors, const std::string& variant);

}  // namespace swarmagg
