#include "reproduce/noa_comparison.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "models/sample_statistics.hpp"
#include "reproduce/paper_predictions.hpp"

namespace swarmagg {

const std::vector<std::string>& noa_variants() {
  static const std::vector<std::string> variants{"original", "collision", kPaperFitVariant,
                                                 kMeasuredVariant};
  return variants;
}

NoaSeries read_noa_series(const std::filesystem::path& csv) {
  return read_step_series(read_csv(csv), "noa");
}

double noa_rmse(const NoaSeries& simulation, const NoaSeries& model) {
  std::map<std::int64_t, double> predicted;
  for (std::size_t i = 0; i < model.steps.size(); ++i) predicted[model.steps[i]] = model.mean_at(i);
  double squares = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < simulation.steps.size(); ++i) {
    const auto found = predicted.find(simulation.steps[i]);
    if (found == predicted.end()) continue;
    const double difference = simulation.mean_at(i) - found->second;
    squares += difference * difference;
    ++count;
  }
  if (count == 0) throw std::runtime_error("simulation and model share no recorded step");
  return std::sqrt(squares / count);
}

NoaComparison compare_noa(const std::filesystem::path& run_folder) {
  NoaComparison comparison;
  comparison.simulation = read_noa_series(run_folder / "timeseries.csv");
  for (const std::string& variant : noa_variants()) {
    comparison.models.push_back(
        read_noa_series(run_folder / "model-timeseries" / ("bayindir-" + variant + ".csv")));
    comparison.errors.push_back(
        {variant, noa_rmse(comparison.simulation, comparison.models.back())});
  }
  return comparison;
}

}  // namespace swarmagg
