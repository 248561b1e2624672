#pragma once
// One column of a timeseries-shaped CSV (a replicate, step and time per row) reduced to its
// mean across replicates at each recorded step, read row by row. A step holds a sum and a
// count, not the replicates' values: a run of 10^6 recorded steps reads into 24 MB, where the
// values side by side (analysis/step_series.hpp) take several times that.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace swarmagg {

struct StepMean {
  std::int64_t step = 0;
  double sum = 0.0;  // of the replicates' values, added in file order
  std::uint64_t count = 0;

  // The same value, bit for bit, as sample_mean of the values in file order.
  double mean() const { return sum / static_cast<double>(count); }
};

// Collects (step, value) in any order into means by increasing step. Rows that come replicate
// by replicate, each with increasing steps (the files swarmagg writes), cost a constant time
// each; a step out of that order is inserted where it belongs.
class StepMeans {
 public:
  void add(std::int64_t step, double value);
  const std::vector<StepMean>& means() const { return means_; }
  std::vector<StepMean> release() { return std::move(means_); }

 private:
  std::vector<StepMean> means_;  // by increasing step
  std::size_t cursor_ = 0;       // where the last row's step is
};

std::vector<StepMean> read_step_means(const std::filesystem::path& csv, const std::string& column);

struct StepSeries;
// The means of a series read whole (its values summed in file order).
std::vector<StepMean> step_means(const StepSeries& series);

}  // namespace swarmagg
