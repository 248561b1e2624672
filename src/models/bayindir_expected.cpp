#include "models/bayindir_expected.hpp"

#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "models/output_grid.hpp"

namespace swarmagg {

double advance_expected(const BayindirRates& rates, BayindirState& state) {
  const double y = state.searching;
  // One agent meets nobody; the original variant's C y^2 is not 0 at y = 1, and with no size
  // of two to hold them its pairs took agents out of the model (searching fell below 1).
  const double creations = state.agents() >= 2 ? rates.creation.at(y) : 0.0;
  state.totals.encounters += creations;
  if (!rates.forms_aggregates) return 0.0;

  std::vector<double>& count = state.aggregates;
  double growths = 0.0, dissipations = 0.0, shrinks = 0.0;
  // Sizes are walked upwards so that each n_m is read before it changes: the flow into n_m
  // from below (creation into n_2, then G_{m-1}) is carried, and S_m goes into n_{m-1},
  // which has already been updated from its old value.
  double inflow_from_below = creations;
  double lowest = 0.0;
  for (int m = 2; m <= state.agents(); ++m) {
    const double grow = count[m] * y * rates.growth[m];
    const double lose = count[m] * rates.loss[m];
    count[m] += inflow_from_below - grow - lose;
    if (m >= 3) {
      count[m - 1] += lose;
      lowest = std::min(lowest, count[m - 1]);  // n_{m-1} is final now
    }
    inflow_from_below = grow;
    growths += grow;
    (m == 2 ? dissipations : shrinks) += lose;
  }
  if (state.agents() >= 2) lowest = std::min(lowest, count[state.agents()]);
  state.searching = y - 2.0 * creations - growths + 2.0 * dissipations + shrinks;
  state.totals.creations += creations;
  state.totals.growths += growths;
  state.totals.dissipations += dissipations;
  state.totals.shrinks += shrinks;
  return lowest;
}

void advance_expected_series(const BayindirRates& rates, BayindirState& state, std::int64_t step,
                             const std::vector<double>& start) {
  if (step == 0 && !start.empty() && rates.forms_aggregates) {
    state = BayindirState::after_first_decision(rates.agents, start);
    return;
  }
  const double lowest = advance_expected(rates, state);
  const double tolerance = 1e-9 * rates.agents;
  if (lowest >= -tolerance && state.searching >= -tolerance &&
      state.searching <= rates.agents + tolerance)
    return;
  throw InputError("the expected model left the range of the agents at step " +
                   std::to_string(step + 1) + " (searching " + std::to_string(state.searching) +
                   ", the smallest aggregate count " + std::to_string(lowest) +
                   "): its rates give more events per step than there are agents");
}

BayindirState walk_expected_series(
    const BayindirRates& rates, const std::vector<std::int64_t>& grid,
    const std::vector<double>& start,
    const std::function<void(const BayindirState&, std::int64_t step)>& record,
    const WalkProgress& progress) {
  BayindirState state = BayindirState::all_searching(rates.agents);
  walk_grid(
      grid, [&](std::int64_t step) { advance_expected_series(rates, state, step, start); },
      [&](std::int64_t step) { record(state, step); }, progress);
  return state;
}

std::vector<ModelRow> bayindir_expected_series(const BayindirRates& rates,
                                               const std::vector<std::int64_t>& grid,
                                               const std::vector<double>& start) {
  std::vector<ModelRow> rows;
  walk_expected_series(rates, grid, start, [&](const BayindirState& state, std::int64_t step) {
    rows.push_back(to_model_row(state, rates.forms_aggregates, true, 0, step));
  });
  return rows;
}

}  // namespace swarmagg
