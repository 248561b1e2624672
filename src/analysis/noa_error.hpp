#pragma once
// The error of an expected NOA series against a simulation's: the RMSE, over the recorded
// steps both hold, between the mean NOA across replicates and the model's (its replicates'
// mean for a stochastic series).
#include <filesystem>

#include "analysis/step_series.hpp"

namespace swarmagg {

using NoaSeries = StepSeries;  // the noa column

// Groups a timeseries-shaped CSV's `noa` column by step.
NoaSeries read_noa_series(const std::filesystem::path& csv);

// Throws std::runtime_error when the two share no recorded step.
double noa_rmse(const NoaSeries& simulation, const NoaSeries& model);

}  // namespace swarmagg
