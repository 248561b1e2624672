#pragma once
// The stochastic Bayindir model: the same per-step events as the expected-value model, drawn
// as whole numbers so that replicates show the spread a simulation's box plots show. Given
// the state, each step's expected events equal the expected-value model's exactly:
//   creations ~ Binomial(floor(y/2), C / floor(y/2)) (each uses two of the y searchers);
//   each aggregate of size m independently grows with probability y g_m, else loses an
//   agent with probability loss_m / (1 - y g_m), i.e. one multinomial draw per size.
// Only if the draws ask for more searchers than exist is growth cut short (not reachable
// while bayindir_rates' probability bound keeps expected use far below y). Collision worlds
// draw encounters ~ Binomial(y(y-1)/2, C / (y(y-1)/2)). Draws come from the counter-based
// generator keyed by (run.seed, replicate), so results are reproducible per seed.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "models/bayindir_rates.hpp"
#include "models/bayindir_state.hpp"
#include "models/binomial_draw.hpp"
#include "models/output_grid.hpp"

namespace swarmagg {

void advance_stochastic(const BayindirRates& rates, BayindirState& state, UniformStream& uniforms);

// The first decision of a stochastic replicate that starts from expected aggregates `start`
// ([m]): whole counts, largest size first, n_m ~ Binomial(floor(free / m), start[m] / that),
// so each count has the expected mean while agents last.
BayindirState draw_first_decision(int agents, const std::vector<double>& start,
                                  UniformStream& uniforms);

// `replicates` independent runs from all searching, one after another: record(state,
// replicate, step) gets each replicate's state at every step of `grid`, replicate by
// replicate. `stream` separates the draws of different variants of one world. With `start`,
// the first step draws the aggregates of the first decision (draw_first_decision) instead of
// creations. `progress` counts the steps of every replicate.
void walk_stochastic_replicates(
    const BayindirRates& rates, const std::vector<std::int64_t>& grid, std::uint64_t seed,
    int replicates, std::uint64_t stream, const std::vector<double>& start,
    const std::function<void(const BayindirState&, int replicate, std::int64_t step)>& record,
    const WalkProgress& progress = {});

// The same runs side by side: record(states, step) gets every replicate's state at each step
// of `grid`, in replicate order, for what needs the replicates together (statistics over
// them). Each replicate and step draws from its own key of the counter-based generator, so
// the states are those of walk_stochastic_replicates.
void walk_stochastic_side_by_side(
    const BayindirRates& rates, const std::vector<std::int64_t>& grid, std::uint64_t seed,
    int replicates, std::uint64_t stream, const std::vector<double>& start,
    const std::function<void(std::span<const BayindirState>, std::int64_t step)>& record,
    const WalkProgress& progress = {});

// The rows of walk_stochastic_replicates, ordered by replicate, then step.
std::vector<ModelRow> bayindir_stochastic_series(const BayindirRates& rates,
                                                 const std::vector<std::int64_t>& grid,
                                                 std::uint64_t seed, int replicates,
                                                 std::uint64_t stream,
                                                 const std::vector<double>& start = {});

}  // namespace swarmagg
