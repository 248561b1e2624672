#pragma once
// Simulated NOA against the Bayindir model variants (Figs 9-19), read from a run folder:
// timeseries.csv and model-timeseries/bayindir-<variant>.csv, which share the record grid.
// The error of a variant is the RMSE, over the recorded steps, between the mean NOA across
// replicates and the variant's expected NOA.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/noa_error.hpp"
#include "analysis/variant_error.hpp"

namespace swarmagg {

// The expected-value variants compared: Bayindir's original, our kinetic collision variant,
// the paper's fitted collision variant, the returns variant (worlds whose aggregates lose
// agents only) and the measured variant.
const std::vector<std::string>& noa_variants();

struct NoaComparison {
  NoaSeries simulation;
  std::vector<NoaSeries> models;     // in noa_variants() order, those the run folder has
  std::vector<VariantError> errors;  // RMSE per variant, same order
  double spread = 0.0;               // the replicates' own (analysis/replicate_spread.hpp)
};

NoaComparison compare_noa(const std::filesystem::path& run_folder);

}  // namespace swarmagg
