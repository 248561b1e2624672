#pragma once
// Text of the model output files (SPEC 7). model.csv is tidy,
// `model,variant,step,time,quantity,value`: every predicted timeseries column of an
// expected-value variant; for a stochastic variant the mean over replicates under the
// column's name plus `name:sd`, and for noa and encounters the box-plot numbers `name:min`,
// `name:q25`, `name:median`, `name:q75`, `name:max`; then the variant's extra values (step
// and time empty when stationary). timeseries_csv has exactly the simulation's
// timeseries.csv columns, one row per replicate and step, empty where not predicted.
#include <string>
#include <vector>

#include "models/model_series.hpp"

namespace swarmagg {

std::string model_csv(const std::vector<VariantPrediction>& predictions, double dt);
std::string timeseries_csv(const VariantPrediction& prediction, double dt);

}  // namespace swarmagg
