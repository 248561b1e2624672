#include "reproduce/noa_comparison.hpp"

#include "analysis/model_errors.hpp"
#include "analysis/replicate_spread.hpp"
#include "models/noise_floor.hpp"
#include "models/return_probability.hpp"
#include "models/sample_statistics.hpp"
#include "reproduce/paper_predictions.hpp"

namespace swarmagg {

const std::vector<std::string>& noa_variants() {
  static const std::vector<std::string> variants{"original", "collision", kPaperFitVariant,
                                                 kReturnsVariant, kMeasuredVariant};
  return variants;
}

NoaComparison compare_noa(const std::filesystem::path& run_folder) {
  NoaComparison comparison;
  comparison.simulation = read_noa_series(run_folder / "timeseries.csv");
  comparison.spread = noa_spread(comparison.simulation);
  const std::map<std::string, double> floors =
      read_noise_floors(run_folder / "model.csv", "bayindir", kNoaMetric);
  for (const std::string& variant : noa_variants()) {
    const std::filesystem::path file =
        run_folder / "model-timeseries" / ("bayindir-" + variant + ".csv");
    // Only worlds whose aggregates lose agents have the returns variant.
    if (variant == kReturnsVariant && !std::filesystem::exists(file)) continue;
    comparison.models.push_back(read_noa_series(file));
    const auto floor = floors.find(variant);
    comparison.errors.push_back(
        {variant, noa_rmse(comparison.simulation, comparison.models.back()),
         floor == floors.end() ? std::nullopt : std::optional(floor->second)});
  }
  return comparison;
}

}  // namespace swarmagg
