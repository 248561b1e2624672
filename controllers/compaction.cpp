#include "controllers/compaction.hpp"

#include <cmath>

namespace swarmagg {

CompactionRule compaction_rule(const WorldSpec& spec) {
  const CompactionSpec& compaction = spec.controller.compaction;
  return {compaction.enabled, spec.compaction_spacing(), compaction.gain, compaction.tolerance};
}

double standing_norm2(double tolerance) {
  if (!(tolerance > 0.0)) return 0.0;
  // tolerance^2 rounds to within an ulp, so at most a few steps down reach a square whose
  // root rounds below the tolerance (or 0, when the square underflows).
  double square = tolerance * tolerance;
  while (square > 0.0 && !(std::sqrt(square) < tolerance)) square = std::nextafter(square, 0.0);
  return square;
}

std::vector<std::string> compaction_keys() {
  return {"controller.compaction.enabled", "controller.compaction.spacing",
          "controller.compaction.gain", "controller.compaction.tolerance"};
}

}  // namespace swarmagg
