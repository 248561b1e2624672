#include "analysis/step_series.hpp"

#include <cmath>
#include <map>

#include "analysis/csv_reader.hpp"
#include "models/sample_statistics.hpp"

namespace swarmagg {

namespace {

StepSeries in_order(StepSeries series, const std::vector<std::size_t>& order) {
  StepSeries ordered;
  for (const std::size_t i : order) {
    ordered.steps.push_back(series.steps[i]);
    ordered.times.push_back(series.times[i]);
    ordered.values.push_back(std::move(series.values[i]));
  }
  return ordered;
}

}  // namespace

double StepSeries::mean_at(std::size_t index) const {
  return sample_mean(values.at(index));
}

std::vector<StepSeries> read_step_series(const std::filesystem::path& csv,
                                         const std::vector<std::string>& columns,
                                         const StepFilter& keep) {
  CsvReader reader(csv);
  const std::size_t step = reader.column("step"), time = reader.column("time");
  std::vector<std::size_t> wanted;
  for (const std::string& column : columns) wanted.push_back(reader.column(column));
  // Rows come replicate by replicate: the steps are found in the first and looked up after.
  std::map<std::int64_t, std::size_t> index_of_step;
  std::vector<StepSeries> series(columns.size());
  while (reader.next()) {
    const std::int64_t s = std::llround(reader.number(step));
    if (keep && !keep(s)) continue;
    const double t = reader.number(time);  // of the step's last row, where they differ
    auto [found, added] = index_of_step.try_emplace(s, index_of_step.size());
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      StepSeries& one = series[k];
      if (added) {
        one.steps.push_back(s);
        one.times.push_back(t);
        one.values.emplace_back();
      }
      one.times[found->second] = t;
      one.values[found->second].push_back(reader.number(wanted[k]));
    }
  }
  // In step order whatever the file's order (the map's order).
  std::vector<std::size_t> order;
  for (const auto& [s, index] : index_of_step) order.push_back(index);
  for (StepSeries& one : series) one = in_order(std::move(one), order);
  return series;
}

StepSeries read_step_series(const std::filesystem::path& csv, const std::string& column,
                            const StepFilter& keep) {
  return std::move(read_step_series(csv, std::vector<std::string>{column}, keep).front());
}

}  // namespace swarmagg
