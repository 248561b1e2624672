#include "reproduce/noa_comparison.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "models/sample_statistics.hpp"
#include "output/csv_table.hpp"
#include "reproduce/paper_predictions.hpp"

namespace swarmagg {

const std::vector<std::string>& noa_variants() {
  static const std::vector<std::string> variants{"original", "collision", kPaperFitVariant,
                                                 kMeasuredVariant};
  return variants;
}

double NoaSeries::mean_at(std::size_t index) const {
  return sample_mean(values.at(index));
}

NoaSeries read_noa_series(const std::filesystem::path& csv) {
  const CsvTable table = read_csv(csv);
  const std::size_t step = table.column("step"), time = table.column("time"),
                    noa = table.column("noa");
  std::map<std::int64_t, std::pair<double, std::vector<double>>> by_step;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    auto& entry = by_step[std::llround(table.number(row, step))];
    entry.first = table.number(row, time);
    entry.second.push_back(table.number(row, noa));
  }
  NoaSeries series;
  for (auto& [s, entry] : by_step) {
    series.steps.push_back(s);
    series.times.push_back(entry.first);
    series.values.push_back(std::move(entry.second));
  }
  return series;
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
