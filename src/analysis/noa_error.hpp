#pragma once
// The error of an expected NOA series against a simulation's: the RMSE, over the recorded
// steps both hold, between the mean NOA across replicates and the model's (its replicates'
// mean for a stochastic series).
#include <filesystem>
#include <vector>

#include "analysis/step_means.hpp"
#include "analysis/step_series.hpp"

namespace swarmagg {

using NoaSeries = StepSeries;  // the noa column

// Groups a timeseries-shaped CSV's `noa` column by step.
NoaSeries read_noa_series(const std::filesystem::path& csv);
// Its means per step only (what an error needs, in a fraction of the memory).
std::vector<StepMean> read_noa_means(const std::filesystem::path& csv);

// Both by increasing step. Throws std::runtime_error when the two share no recorded step.
double noa_rmse(const std::vector<StepMean>& simulation, const std::vector<StepMean>& model);
double noa_rmse(const NoaSeries& simulation, const NoaSeries& model);

}  // namespace swarmagg
