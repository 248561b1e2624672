#pragma once
// rates.json (docs/models.md): every measured term with its 95% interval and, per model variant,
// the model's value and the ratio measured / model with its interval; the initial state;
// which terms are not measured yet and why; what the measured variant took from the model;
// the resolved world they were measured in (`resolved_world`, world_to_yaml), so that rates
// fed to another world's model can be told (rates/rates_origin.hpp).
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "rates/rate_rows.hpp"
#include "rates/rate_tally.hpp"

namespace swarmagg {

std::string rates_json(const WorldSpec& world, const RateTally& tally,
                       const std::vector<RateRow>& rows);

}  // namespace swarmagg
