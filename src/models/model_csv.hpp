#pragma once
// Text of the model output files (docs/reference/outputs.md). model.csv is tidy,
// `model,variant,step,time,quantity,value`: an expected-value variant's predicted columns
// (not `waiting`, which is N - searching); for a stochastic variant, statistics over the
// replicates: for noa and encounters the mean (under the column's name), `name:sd` and the
// box-plot numbers `name:min`, `name:q25`, `name:median`, `name:q75`, `name:max`; for
// searching and largest the mean and `name:sd`; then the variant's extra values (step and
// time empty when stationary). model_timeseries_csv has exactly the simulation's
// timeseries.csv columns, one row per replicate and step, empty where not predicted.
#include <span>
#include <string>
#include <vector>

#include "models/model_series.hpp"

namespace swarmagg {

std::string model_csv(const std::vector<VariantPrediction>& predictions, double dt);
std::string model_timeseries_csv(const VariantPrediction& prediction, double dt);

// The same texts in pieces, for outputs written while the model runs (run/model_outputs.hpp).
// model.csv: its header; then per variant its series, an expected-value variant's row by row
// and a stochastic variant's step by step (`rows`: every replicate's row at one step); then
// its extra values.
inline constexpr const char* kModelCsvHeader = "model,variant,step,time,quantity,value\n";
void append_expected_row(std::string& out, const VariantPrediction& variant, const ModelRow& row,
                         double dt);
void append_replicate_statistics(std::string& out, const VariantPrediction& variant,
                                 std::span<const ModelRow* const> rows, double dt);
void append_extra_values(std::string& out, const VariantPrediction& variant, double dt);
// A model timeseries file: its header, then its rows.
std::string model_timeseries_header();
void append_timeseries_row(std::string& out, const ModelRow& row, double dt);

}  // namespace swarmagg
