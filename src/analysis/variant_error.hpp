#pragma once
// How far one model variant is from the simulation, by the measure of its comparison (RMSE
// of mean NOA, total-variation distance of partition distributions).
#include <optional>
#include <string>

namespace swarmagg {

// The model variant fed with a run's measured terms (models/measured_rates.hpp); judged
// beside the paper's variants, never counted as one of them.
inline constexpr const char* kMeasuredVariant = "measured";

struct VariantError {
  std::string variant;
  double error = 0.0;
  // The error the variant shows against its own simulated process with the same replicates
  // and run length (models/noise_floor.hpp); empty where model.csv has none.
  std::optional<double> noise_floor = {};
};

}  // namespace swarmagg
