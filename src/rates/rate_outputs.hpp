#pragma once
// The measured-rates outputs of a run (docs/models.md), written atomically into a folder:
// rates.csv, rates.json and a plot per term (rates-<term>.png, drawn when gnuplot is
// installed, its script and CSV beside it either way).
#include <filesystem>
#include <vector>

#include "config/world_spec.hpp"
#include "rates/rate_rows.hpp"
#include "rates/rate_tally.hpp"

namespace swarmagg {

// Whether the plot of each term is drawn, or only its gnuplot script and CSV written (the
// runs of `reproduce` and `run --no-plots`: `gnuplot rates-<term>.gp` in the folder draws it).
enum class RatePlots { Draw, ScriptsOnly };

// Writes `rows` (measured_rate_rows of the tally). Without gnuplot the plots' scripts and CSVs
// are written undrawn, with a note on stderr.
void write_rate_outputs(const WorldSpec& world, const RateTally& tally,
                        const std::vector<RateRow>& rows, const std::filesystem::path& folder,
                        RatePlots plots = RatePlots::Draw);

}  // namespace swarmagg
