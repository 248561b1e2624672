#pragma once
// The predictions reproduce writes beside each run: every variant pending_predictions(world)
// gives and, for the Bayindir model, the collision variant under the paper's fitted constant
// (model.kappa: paper, Z = C s v N^2) as variant `collision-paper`, so the plots and the
// report can show the paper's own improved model next to our kinetic one.
#include <vector>

#include "analysis/variant_error.hpp"
#include "config/world_spec.hpp"
#include "models/initial_state.hpp"
#include "models/measured_terms.hpp"
#include "models/pending_variant.hpp"

namespace swarmagg {

inline constexpr const char* kPaperFitVariant = "collision-paper";

// With `measured` terms, the measured variants too; `sample` as pending_predictions() needs
// it (models/predictions.hpp).
std::vector<PendingVariant> paper_predictions(const WorldSpec& world, const MeasuredTerms* measured,
                                              const PlacementSample* sample);

}  // namespace swarmagg
