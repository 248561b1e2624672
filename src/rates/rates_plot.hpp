#pragma once
// One plot per measured term, in <folder>/rates-<term>.{csv,gp,png}: the measured rate by
// size with its 95% interval (sizes with too few events are left out), each model
// variant's curve and, for creation, the paper's fitted constant. Terms without sizes show
// the measurement and each model's value side by side.
#include <filesystem>
#include <vector>

#include "config/world_spec.hpp"
#include "rates/rate_rows.hpp"

namespace swarmagg {

// Throws std::runtime_error when gnuplot fails (see plot/gnuplot.hpp).
void plot_rates(const WorldSpec& world, const std::vector<RateRow>& rows,
                const std::filesystem::path& folder);

// The CSVs and gnuplot scripts of plot_rates, without drawing them.
void write_rate_plot_scripts(const WorldSpec& world, const std::vector<RateRow>& rows,
                             const std::filesystem::path& folder);

}  // namespace swarmagg
