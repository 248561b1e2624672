#pragma once
// rates.csv (docs/models.md), tidy: term,size,events,exposure,rate,ci_low,ci_high,model,variant,
// model_rate. One row per model variant that predicts the term (a term with no model has
// one row with the last three empty); rate and interval are empty when there were too few
// events; size is empty where it does not apply. Rates are per tu (the `initial` term:
// aggregates per replicate).
#include <filesystem>
#include <string>
#include <vector>

#include "rates/rate_rows.hpp"

namespace swarmagg {

std::string rates_csv(const std::vector<RateRow>& rows);

// Reads rates.csv back into rows (model columns merged per term and size). Throws
// InputError naming the file and line when it is not a rates.csv.
std::vector<RateRow> read_rates_csv(const std::filesystem::path& file);

}  // namespace swarmagg
