#pragma once
// Columns of a timeseries-shaped CSV (timeseries.csv, model-timeseries/*.csv: a replicate,
// step and time per row) grouped by step, with the replicates' values side by side, so
// statistics across replicates are taken per recorded step. The file is read row by row:
// only the numbers asked for, at the steps asked for, are held.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace swarmagg {

struct StepSeries {
  std::vector<std::int64_t> steps;          // increasing
  std::vector<double> times;                // of each step
  std::vector<std::vector<double>> values;  // per step, one value per replicate, in file order

  double mean_at(std::size_t index) const;
};

// Which steps a reader keeps (none given: every step), so that a plot of a long run holds
// only the points it draws.
using StepFilter = std::function<bool(std::int64_t step)>;

// One series per column, in the order asked.
std::vector<StepSeries> read_step_series(const std::filesystem::path& csv,
                                         const std::vector<std::string>& columns,
                                         const StepFilter& keep = {});
StepSeries read_step_series(const std::filesystem::path& csv, const std::string& column,
                            const StepFilter& keep = {});

}  // namespace swarmagg
