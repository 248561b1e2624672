#pragma once
// The `returns` model variant: the world's own model (model.leaving for Soysal, model.creation
// for Bayindir) whose aggregates lose only the leavers that do not come back, L(i) (1 - q(i))
// with q(i) predicted from the world's parameters (models/return_probability.hpp). Joins stay
// the model's encounter rates: they are meant as new encounters.
#include "config/world_spec.hpp"
#include "models/bayindir_rates.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

SoysalRates returns_soysal_rates(const WorldSpec& world);
BayindirRates returns_bayindir_rates(const WorldSpec& world);

}  // namespace swarmagg
