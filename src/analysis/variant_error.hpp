#pragma once
// How far one model variant is from the simulation, by the measure of its comparison (RMSE
// of mean NOA, total-variation distance of partition distributions).
#include <string>

namespace swarmagg {

struct VariantError {
  std::string variant;
  double error = 0.0;
};

}  // namespace swarmagg
