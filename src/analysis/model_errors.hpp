#pragma once
// Every model variant's error beside its noise floor (models/noise_floor.hpp), read from a
// finished run folder: `tv_partition` for the partition model (analysis/partition_comparison),
// `rmse_noa` for the Bayindir model's expected-value variants (analysis/noa_error). A run
// writes them into summary.json as `model_errors`: [{variant, metric, value, noise_floor}].
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/variant_error.hpp"

namespace swarmagg {

struct ModelError {
  std::string metric;  // tv_partition | rmse_noa
  VariantError error;
};

// variant -> noise floor of `metric`, from model.csv's noise_floor:<metric> rows of `model`.
std::map<std::string, double> read_noise_floors(const std::filesystem::path& model_csv,
                                                const std::string& model,
                                                const std::string& metric);

// Empty without model.csv. Bayindir: every expected-value variant with a file in
// model-timeseries/ (the -stochastic ones are the spreads, not predictions of the mean).
std::vector<ModelError> run_model_errors(const std::filesystem::path& run_folder);

nlohmann::json model_errors_json(const std::vector<ModelError>& errors);

// Adds (or replaces) summary.json's model_errors, atomically; InputError when summary.json
// or a series is damaged.
void write_model_errors(const std::filesystem::path& run_folder);
// Removes them: a model of another run replaced the one they described.
void remove_model_errors(const std::filesystem::path& run_folder);

}  // namespace swarmagg
