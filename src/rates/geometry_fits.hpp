#pragma once
// The aggregate geometry laws of docs/models.md fitted to the measured `radius` and `rim` rows
// (rates/rate_rows.hpp), over the sizes whose mean was measured (enough observations),
// weighted by their observations (rates/power_law_fit.hpp):
//   R1 = r a m^b           fitted as R1 / r = a m^b
//   rim = pi (a m^b - 1)   fitted as rim / pi + 1 = a m^b
// The paper's Fig 6 gives a = 1.20, b = 0.48 for both (models/aggregate_shape.hpp).
// Computed from the rows alone, so rates.csv read back gives the same fits.
#include <nlohmann/json.hpp>
#include <vector>

#include "rates/power_law_fit.hpp"
#include "rates/rate_rows.hpp"

namespace swarmagg {

struct GeometryFits {
  PowerLawFit radius;
  PowerLawFit rim;
};

// `agent_radius`: r of the world (robots.radius).
GeometryFits fit_geometry_laws(const std::vector<RateRow>& rows, double agent_radius);

// {radius: {law, a, a_ci95, b, b_ci95, sizes, paper_a_in_ci, paper_b_in_ci} or
// {law, sizes, refused}, rim: the same, paper: {a, b}}.
nlohmann::json geometry_fits_json(const GeometryFits& fits);

}  // namespace swarmagg
