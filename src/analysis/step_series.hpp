#pragma once
// One column of a timeseries-shaped CSV (timeseries.csv, model-timeseries/*.csv: a
// replicate, step and time per row) grouped by step, with the replicates' values side by
// side, so statistics across replicates are taken per recorded step.
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/csv_table.hpp"

namespace swarmagg {

struct StepSeries {
  std::vector<std::int64_t> steps;          // increasing
  std::vector<double> times;                // of each step
  std::vector<std::vector<double>> values;  // per step, one value per replicate, in file order

  double mean_at(std::size_t index) const;
};

StepSeries read_step_series(const CsvTable& table, const std::string& column);

}  // namespace swarmagg
