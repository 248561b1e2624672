#include "analysis/step_series.hpp"

#include <cmath>
#include <map>

#include "models/sample_statistics.hpp"

namespace swarmagg {

double StepSeries::mean_at(std::size_t index) const {
  return sample_mean(values.at(index));
}

StepSeries read_step_series(const CsvTable& table, const std::string& column) {
  const std::size_t step = table.column("step"), time = table.column("time"),
                    value = table.column(column);
  std::map<std::int64_t, std::pair<double, std::vector<double>>> by_step;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    auto& entry = by_step[std::llround(table.number(row, step))];
    entry.first = table.number(row, time);
    entry.second.push_back(table.number(row, value));
  }
  StepSeries series;
  for (auto& [s, entry] : by_step) {
    series.steps.push_back(s);
    series.times.push_back(entry.first);
    series.values.push_back(std::move(entry.second));
  }
  return series;
}

}  // namespace swarmagg
