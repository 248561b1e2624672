#pragma once
// How far one model variant is from the simulation, by the measure of its comparison (RMSE
// of mean NOA, total-variation distance of partition distributions).
#include <string>

namespace swarmagg {

// The model variant fed with a run's measured terms (models/measured_rates.hpp); judged
// beside the paper's variants, never counted as one of them.
inline constexpr const char* kMeasuredVariant = "measured";

struct VariantError {
  std::string variant;
  double error = 0.0;
};

}  // namespace swarmagg
