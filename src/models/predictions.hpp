#pragma once
// Every macroscopic prediction that applies to a world (SPEC 5): bayindir and collision
// controllers get the Bayindir model, variants `original` and `collision` (expected values)
// and `original-stochastic`, `collision-stochastic` (model.stochastic_replicates seeded
// replicates); soysal controllers get the partition model, variants `original` and
// `peripheral`. Each variant reads the same WorldSpec the simulator runs; the ones the
// world's model block names (model.creation, model.leaving) are marked `chosen`.
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "models/model_series.hpp"

namespace swarmagg {

std::vector<VariantPrediction> predict(const WorldSpec& world);

// Where the world departs from the models' assumptions, one sentence each.
std::vector<std::string> model_caveats(const WorldSpec& world);

// One line per variant: the final expected NOA and, for the partition model, the most
// likely stationary partition.
std::string prediction_summary(const VariantPrediction& prediction);

}  // namespace swarmagg
