#include "analysis/noa_error.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "analysis/csv_table.hpp"

namespace swarmagg {

NoaSeries read_noa_series(const std::filesystem::path& csv) {
  return read_step_series(csv, "noa");
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

}  // namespace swarmagg
