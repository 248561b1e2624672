#include "models/bayindir_stochastic.hpp"

#include <algorithm>

#include "models/output_grid.hpp"

namespace swarmagg {

namespace {

// Draws `trials` events of total expectation `expected` as Binomial(trials, expected/trials):
// the mean is exact and the count never exceeds the trials available.
std::int64_t draw_with_mean(std::int64_t trials, double expected, UniformStream& uniforms) {
  if (trials <= 0) return 0;
  return binomial_draw(trials, expected / static_cast<double>(trials), uniforms);
}

void count_encounters(const BayindirRates& rates, BayindirState& state, UniformStream& uniforms) {
  const auto y = static_cast<std::int64_t>(state.searching);
  const std::int64_t pairs = y * (y - 1) / 2;
  state.totals.encounters +=
      static_cast<double>(draw_with_mean(pairs, rates.creation.at(y), uniforms));
}

}  // namespace

void advance_stochastic(const BayindirRates& rates, BayindirState& state, UniformStream& uniforms) {
  if (!rates.forms_aggregates) {
    count_encounters(rates, state, uniforms);
    return;
  }
  const auto y = static_cast<std::int64_t>(state.searching);
  const std::int64_t creations = draw_with_mean(y / 2, rates.creation.at(y), uniforms);
  std::int64_t searchers_left = y - 2 * creations;
  std::int64_t growths = 0, dissipations = 0, shrinks = 0;
  std::vector<double>& count = state.aggregates;
  // Same upward walk as the expected-value model: n_m is read before it changes. Above the
  // largest aggregate present, plus the one size it can grow into, nothing is drawn and
  // nothing changes, so the walk stops there.
  const int last =
      std::min(state.agents(), std::max(2, static_cast<int>(state.largest_present()) + 1));
  std::int64_t inflow_from_below = creations;
  for (int m = 2; m <= last; ++m) {
    const auto present = static_cast<std::int64_t>(count[m]);
    std::int64_t grow = 0, lose = 0;
    if (present > 0) {
      const double grow_probability = static_cast<double>(y) * rates.growth[m];
      grow = std::min(binomial_draw(present, grow_probability, uniforms), searchers_left);
      lose = binomial_draw(present - grow, rates.loss[m] / (1.0 - grow_probability), uniforms);
    }
    searchers_left -= grow;
    count[m] += static_cast<double>(inflow_from_below - grow - lose);
    if (m >= 3) count[m - 1] += static_cast<double>(lose);
    inflow_from_below = grow;
    growths += grow;
    (m == 2 ? dissipations : shrinks) += lose;
  }
  state.size_bound = last;
  state.searching = static_cast<double>(searchers_left + 2 * dissipations + shrinks);
  state.totals.creations += static_cast<double>(creations);
  state.totals.encounters += static_cast<double>(creations);
  state.totals.growths += static_cast<double>(growths);
  state.totals.dissipations += static_cast<double>(dissipations);
  state.totals.shrinks += static_cast<double>(shrinks);
}

BayindirState draw_first_decision(int agents, const std::vector<double>& start,
                                  UniformStream& uniforms) {
  std::vector<double> drawn(static_cast<std::size_t>(agents) + 1, 0.0);
  std::int64_t free = agents;
  for (int m = std::min<int>(agents, static_cast<int>(start.size()) - 1); m >= 2; --m) {
    const std::int64_t count =
        draw_with_mean(free / m, start[static_cast<std::size_t>(m)], uniforms);
    drawn[static_cast<std::size_t>(m)] = static_cast<double>(count);
    free -= m * count;
  }
  return BayindirState::after_first_decision(agents, drawn);
}

namespace {

// Step `step` of one replicate, keyed by `rng` (its replicate) and `stream` (its variant).
void advance_replicate(const BayindirRates& rates, BayindirState& state, const CounterRng& rng,
                       std::int64_t step, std::uint64_t stream, const std::vector<double>& start) {
  UniformStream uniforms(rng, static_cast<std::uint64_t>(step), stream);
  if (step == 0 && !start.empty() && rates.forms_aggregates) {
    state = draw_first_decision(rates.agents, start, uniforms);
  } else {
    advance_stochastic(rates, state, uniforms);
  }
}

CounterRng replicate_rng(std::uint64_t seed, int replicate) {
  return CounterRng::for_replicate(seed, static_cast<std::uint64_t>(replicate));
}

}  // namespace

void walk_stochastic_replicates(
    const BayindirRates& rates, const std::vector<std::int64_t>& grid, std::uint64_t seed,
    int replicates, std::uint64_t stream, const std::vector<double>& start,
    const std::function<void(const BayindirState&, int replicate, std::int64_t step)>& record,
    const WalkProgress& progress) {
  for (int replicate = 0; replicate < replicates; ++replicate) {
    const CounterRng rng = replicate_rng(seed, replicate);
    BayindirState state = BayindirState::all_searching(rates.agents);
    walk_grid(
        grid, [&](std::int64_t step) { advance_replicate(rates, state, rng, step, stream, start); },
        [&](std::int64_t step) { record(state, replicate, step); }, progress);
  }
}

void walk_stochastic_side_by_side(
    const BayindirRates& rates, const std::vector<std::int64_t>& grid, std::uint64_t seed,
    int replicates, std::uint64_t stream, const std::vector<double>& start,
    const std::function<void(std::span<const BayindirState>, std::int64_t step)>& record,
    const WalkProgress& progress) {
  const auto count = static_cast<std::size_t>(std::max(replicates, 0));
  std::vector<CounterRng> rngs;
  for (int replicate = 0; replicate < replicates; ++replicate)
    rngs.push_back(replicate_rng(seed, replicate));
  std::vector<BayindirState> states(count, BayindirState::all_searching(rates.agents));
  WalkProgress replicate_steps;
  if (progress) {
    replicate_steps = [&](std::int64_t steps) { progress(steps * replicates); };
  }
  walk_grid(
      grid,
      [&](std::int64_t step) {
        for (std::size_t k = 0; k < count; ++k)
          advance_replicate(rates, states[k], rngs[k], step, stream, start);
      },
      [&](std::int64_t step) { record(states, step); }, replicate_steps);
}

std::vector<ModelRow> bayindir_stochastic_series(const BayindirRates& rates,
                                                 const std::vector<std::int64_t>& grid,
                                                 std::uint64_t seed, int replicates,
                                                 std::uint64_t stream,
                                                 const std::vector<double>& start) {
  std::vector<ModelRow> rows;
  rows.reserve(grid.size() * static_cast<std::size_t>(std::max(replicates, 0)));
  walk_stochastic_replicates(
      rates, grid, seed, replicates, stream, start,
      [&](const BayindirState& state, int replicate, std::int64_t step) {
        rows.push_back(to_model_row(state, rates.forms_aggregates, false, replicate, step));
      });
  return rows;
}

}  // namespace swarmagg
