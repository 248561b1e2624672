#pragma once
// sweep_summary.csv: per parameter point and observable, statistics over the replicates of
// the final value (the last timeseries row): replicates, mean, sd (n - 1), and the
// quantiles min, q25, median, q75, max (type 7, as R and numpy). Tidy: one row per point
// and observable, the parameter values first.
#include <string>
#include <vector>

namespace swarmagg {

struct PointFinals {
  std::vector<std::string> values;              // the point's parameter values, in column order
  std::vector<std::vector<double>> replicates;  // [replicate][observable]
};

std::string sweep_summary_csv(const std::vector<std::string>& parameter_keys,
                              const std::vector<std::string>& observables,
                              const std::vector<PointFinals>& points);

}  // namespace swarmagg
