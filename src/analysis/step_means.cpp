#include "analysis/step_means.hpp"

#include <cmath>
#include <numeric>

#include "analysis/csv_reader.hpp"
#include "analysis/step_series.hpp"

namespace swarmagg {

void StepMeans::add(std::int64_t step, double value) {
  // A step below the last one starts the next replicate: the search starts over.
  if (cursor_ < means_.size() && step < means_[cursor_].step) cursor_ = 0;
  while (cursor_ < means_.size() && means_[cursor_].step < step) ++cursor_;
  if (cursor_ == means_.size() || means_[cursor_].step != step)
    means_.insert(means_.begin() + static_cast<std::ptrdiff_t>(cursor_), StepMean{step});
  StepMean& mean = means_[cursor_];
  mean.sum += value;
  ++mean.count;
}

std::vector<StepMean> read_step_means(const std::filesystem::path& csv, const std::string& column) {
  CsvReader reader(csv);
  const std::size_t step = reader.column("step"), time = reader.column("time"),
                    wanted = reader.column(column);
  StepMeans means;
  while (reader.next()) {
    // Unused, but read as read_step_series reads it: a file it would refuse is refused here.
    reader.number(time);
    means.add(std::llround(reader.number(step)), reader.number(wanted));
  }
  return means.release();
}

std::vector<StepMean> step_means(const StepSeries& series) {
  std::vector<StepMean> means;
  means.reserve(series.steps.size());
  for (std::size_t i = 0; i < series.steps.size(); ++i) {
    const std::vector<double>& values = series.values[i];
    means.push_back(
        {series.steps[i], std::accumulate(values.begin(), values.end(), 0.0), values.size()});
  }
  return means;
}

}  // namespace swarmagg
