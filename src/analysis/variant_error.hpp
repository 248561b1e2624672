#pragma once
// How far one model variant is from the simulation, by the measure of its comparison (RMSE
// of mean NOA, total-variation distance of partition distributions).
#include <optional>
#include <string>
#include <vector>

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

// A variant fits when its error is within this multiple of its noise floor.
inline constexpr double kFitsWithin = 2.0;

inline const VariantError* find_error(const std::vector<VariantError>& errors,
                                      const std::string& name) {
  for (const VariantError& e : errors) {
    if (e.variant == name) return &e;
  }
  return nullptr;
}

// The variant's error over its noise floor; none without the variant or a positive floor.
inline std::optional<double> ratio_of(const std::vector<VariantError>& errors,
                                      const std::string& name) {
  const VariantError* e = find_error(errors, name);
  if (!e || !e->noise_floor || *e->noise_floor <= 0.0) return std::nullopt;
  return e->error / *e->noise_floor;
}

}  // namespace swarmagg
