#pragma once
// The measured-rates outputs of a run (docs/models.md), written atomically into a folder:
// rates.csv, rates.json and, when gnuplot is installed, a plot per term (rates-<term>.png).
#include <filesystem>
#include <vector>

#include "config/world_spec.hpp"
#include "rates/rate_rows.hpp"
#include "rates/rate_tally.hpp"

namespace swarmagg {

// Returns the rows written. Without gnuplot the plots are skipped with a note on stderr.
std::vector<RateRow> write_rate_outputs(const WorldSpec& world, const RateTally& tally,
                                        const std::filesystem::path& folder);

}  // namespace swarmagg
