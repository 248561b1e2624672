#include "analysis/run_stationarity.hpp"

#include <cmath>
#include <vector>

#include "models/sample_statistics.hpp"

namespace swarmagg {

NoaTrend second_half_trend(const StepSeries& noa) {
  const std::size_t first = noa.steps.size() / 2;
  if (noa.steps.size() - first < 2) return {};
  const std::size_t replicates = noa.values[first].size();
  double mean_time = 0.0;
  for (std::size_t i = first; i < noa.steps.size(); ++i) mean_time += noa.times[i];
  mean_time /= static_cast<double>(noa.steps.size() - first);
  double spread = 0.0;
  for (std::size_t i = first; i < noa.steps.size(); ++i)
    spread += (noa.times[i] - mean_time) * (noa.times[i] - mean_time);
  const double length = noa.times.back() - noa.times[first];
  std::vector<double> changes;
  int frozen = 0;
  for (std::size_t k = 0; k < replicates; ++k) {
    double covariance = 0.0;
    bool constant = true;
    for (std::size_t i = first; i < noa.steps.size(); ++i) {
      if (k >= noa.values[i].size()) continue;
      covariance += (noa.times[i] - mean_time) * noa.values[i][k];
      constant = constant && noa.values[i][k] == noa.values[first][k];
    }
    changes.push_back(covariance / spread * length);
    frozen += constant ? 1 : 0;
  }
  const MeanInterval interval = mean_interval(changes);
  NoaTrend trend{.change = interval.mean};
  trend.low = interval.mean - interval.half_width;
  trend.high = interval.mean + interval.half_width;
  trend.frozen = frozen;
  trend.replicates = static_cast<int>(replicates);
  return trend;
}

std::map<int, double> value_distribution(const StepSeries& series) {
  std::map<int, double> counts;
  double total = 0.0;
  for (const std::vector<double>& values : series.values) {
    for (const double v : values) {
      counts[static_cast<int>(std::lround(v))] += 1.0;
      total += 1.0;
    }
  }
  for (auto& [value, count] : counts) count /= total;
  return counts;
}

}  // namespace swarmagg
