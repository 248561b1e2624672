#pragma once
// The expected-value Bayindir model (docs/models.md): per step, with every event computed from the
// state before the step,
//   C = creation(y), G_m = n_m y g_m, D = loss_2 n_2, S_m = loss_m n_m (m >= 3),
//   y' = y - 2C - sum G_m + 2D + sum S_m,  n_2' = n_2 + C - D - G_2 + S_3,
//   n_m' = n_m + G_{m-1} - G_m + S_{m+1} - S_m.
// Every event moves agents between y and the n_m, so y + sum m n_m = N is conserved.
#include <cstdint>
#include <functional>
#include <vector>

#include "models/bayindir_rates.hpp"
#include "models/bayindir_state.hpp"
#include "models/output_grid.hpp"

namespace swarmagg {

// Returns the smallest n_m after the step: rates of nearly one event per agent and step (or
// more) overshoot, and a count falls below zero.
double advance_expected(const BayindirRates& rates, BayindirState& state);

// Step `step` of a series that starts from all searching. With `start` (the aggregates after
// the first decision, models/initial_state.hpp) step 0 forms exactly those instead of the
// rates' creations. Throws InputError, naming the step, where it leaves the range of the
// agents (a count below zero, or more searchers than agents): the counts would go on to NaN.
void advance_expected_series(const BayindirRates& rates, BayindirState& state, std::int64_t step,
                             const std::vector<double>& start);

// Hands record(state, step) the state at each step of `grid` (increasing, from 0), stepped
// by advance_expected_series from all searching; returns the state at the last step.
BayindirState walk_expected_series(
    const BayindirRates& rates, const std::vector<std::int64_t>& grid,
    const std::vector<double>& start,
    const std::function<void(const BayindirState&, std::int64_t step)>& record,
    const WalkProgress& progress = {});

// The rows of walk_expected_series.
std::vector<ModelRow> bayindir_expected_series(const BayindirRates& rates,
                                               const std::vector<std::int64_t>& grid,
                                               const std::vector<double>& start = {});

}  // namespace swarmagg
