#pragma once
// Whether a run was stationary where the model comparison assumes it, and the distributions
// of NOA and of the largest aggregate over the run, from timeseries.csv (every recorded
// step of every replicate). Stationary: no NOA trend over the second half of the run, i.e.
// the 95% interval (Student t over replicates) of each replicate's least-squares NOA slope
// over its second half, times the half's length, holds 0.
#include <map>

#include "analysis/step_series.hpp"

namespace swarmagg {

struct NoaTrend {
  double change = 0.0;           // mean NOA change over the second half (slope x its length)
  double low = 0.0, high = 0.0;  // its 95% interval (equal to change with one replicate)
  // Replicates whose NOA kept one value over the whole second half, of `replicates`: a run
  // whose replicates all kept theirs does not mix its NOA, though no trend shows either.
  int frozen = 0;
  int replicates = 0;
  // Rounding leaves a flat run's slope a few ulps from 0: within kFlat counts as flat.
  static constexpr double kFlat = 1e-9;
  bool stationary() const { return low <= kFlat && -kFlat <= high; }
};

// replicates == 0 (no trend) when the second half holds fewer than 2 recorded steps.
NoaTrend second_half_trend(const StepSeries& noa);

// value -> fraction of the recorded rows (all replicates pooled) that held it.
std::map<int, double> value_distribution(const StepSeries& series);

}  // namespace swarmagg
