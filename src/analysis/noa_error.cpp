#include "analysis/noa_error.hpp"

#include <cmath>
#include <stdexcept>

namespace swarmagg {

NoaSeries read_noa_series(const std::filesystem::path& csv) {
  return read_step_series(csv, "noa");
}

std::vector<StepMean> read_noa_means(const std::filesystem::path& csv) {
  return read_step_means(csv, "noa");
}

// A merge of the two step orders: the squares are added in the simulation's step order.
double noa_rmse(const std::vector<StepMean>& simulation, const std::vector<StepMean>& model) {
  double squares = 0.0;
  int count = 0;
  auto predicted = model.begin();
  for (const StepMean& simulated : simulation) {
    while (predicted != model.end() && predicted->step < simulated.step) ++predicted;
    if (predicted == model.end()) break;
    if (predicted->step != simulated.step) continue;
    const double difference = simulated.mean() - predicted->mean();
    squares += difference * difference;
    ++count;
  }
  if (count == 0) throw std::runtime_error("simulation and model share no recorded step");
  return std::sqrt(squares / count);
}

double noa_rmse(const NoaSeries& simulation, const NoaSeries& model) {
  return noa_rmse(step_means(simulation), step_means(model));
}

}  // namespace swarmagg
