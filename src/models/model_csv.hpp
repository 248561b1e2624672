#pragma once
// Text of the model output files (docs/reference/outputs.md). model.csv is tidy,
// `model,variant,step,time,quantity,value`: an expected-value variant's predicted columns
// (not `waiting`, which is N - searching); for a stochastic variant, statistics over the
// replicates: for noa and encounters the mean (under the column's name), `name:sd` and the
// box-plot numbers `name:min`, `name:q25`, `name:median`, `name:q75`, `name:max`; for
// searching and largest the mean and `name:sd`; then the variant's extra values (step and
// time empty when stationary). model_timeseries_csv has exactly the simulation's
// timeseries.csv columns, one row per replicate and step, empty where not predicted.
#include <string>
#include <vector>

#include "models/model_series.hpp"

namespace swarmagg {

std::string model_csv(const std::vector<VariantPrediction>& predictions, double dt);
std::string model_timeseries_csv(const VariantPrediction& prediction, double dt);

}  // namespace swarmagg
