#include "models/bayindir_expected.hpp"

#include "models/output_grid.hpp"

namespace swarmagg {

void advance_expected(const BayindirRates& rates, BayindirState& state) {
  const double y = state.searching;
  const double creations = rates.creation.at(y);
  state.totals.encounters += creations;
  if (!rates.forms_aggregates) return;

  std::vector<double>& count = state.aggregates;
  double growths = 0.0, dissipations = 0.0, shrinks = 0.0;
  // Sizes are walked upwards so that each n_m is read before it changes: the flow into n_m
  // from below (creation into n_2, then G_{m-1}) is carried, and S_m goes into n_{m-1},
  // which has already been updated from its old value.
  double inflow_from_below = creations;
  for (int m = 2; m <= state.agents(); ++m) {
    const double grow = count[m] * y * rates.growth[m];
    const double lose = count[m] * rates.loss[m];
    count[m] += inflow_from_below - grow - lose;
    if (m >= 3) count[m - 1] += lose;
    inflow_from_below = grow;
    growths += grow;
    (m == 2 ? dissipations : shrinks) += lose;
  }
  state.searching = y - 2.0 * creations - growths + 2.0 * dissipations + shrinks;
  state.totals.creations += creations;
  state.totals.growths += growths;
  state.totals.dissipations += dissipations;
  state.totals.shrinks += shrinks;
}

std::vector<ModelRow> bayindir_expected_series(const BayindirRates& rates,
                                               const std::vector<std::int64_t>& grid,
                                               const std::vector<double>& start,
                                               BayindirState* last) {
  BayindirState state = BayindirState::all_searching(rates.agents);
  std::vector<ModelRow> rows;
  walk_grid(
      grid,
      [&](std::int64_t step) {
        if (step == 0 && !start.empty() && rates.forms_aggregates) {
          state = BayindirState::after_first_decision(rates.agents, start);
        } else {
          advance_expected(rates, state);
        }
      },
      [&](std::int64_t step) {
        rows.push_back(to_model_row(state, rates.forms_aggregates, true, 0, step));
      });
  if (last) *last = state;
  return rows;
}

}  // namespace swarmagg
