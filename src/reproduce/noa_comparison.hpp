#pragma once
// Simulated NOA against the Bayindir model variants (Figs 9-19), read from a run folder:
// timeseries.csv and model-timeseries/bayindir-<variant>.csv, which share the record grid.
// The error of a variant is the RMSE, over the recorded steps, between the mean NOA across
// replicates and the variant's expected NOA.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/step_series.hpp"
#include "analysis/variant_error.hpp"

namespace swarmagg {

// The expected-value variants compared: Bayindir's original, our kinetic collision variant
// and the paper's fitted collision variant.
const std::vector<std::string>& noa_variants();

using NoaSeries = StepSeries;  // the noa column

struct NoaComparison {
  NoaSeries simulation;
  std::vector<NoaSeries> models;     // in noa_variants() order
  std::vector<VariantError> errors;  // RMSE per variant, same order
};

// Groups a timeseries-shaped CSV's `noa` column by step.
NoaSeries read_noa_series(const std::filesystem::path& csv);

// RMSE between the replicate mean of `simulation` and the model, over the steps both hold.
double noa_rmse(const NoaSeries& simulation, const NoaSeries& model);

NoaComparison compare_noa(const std::filesystem::path& run_folder);

}  // namespace swarmagg
