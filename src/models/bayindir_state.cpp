#include "models/bayindir_state.hpp"

#include <algorithm>
#include <numeric>

namespace swarmagg {

BayindirState BayindirState::all_searching(int agents) {
  BayindirState state;
  state.searching = agents;
  state.aggregates.assign(agents + 1, 0.0);
  return state;
}

BayindirState BayindirState::after_first_decision(int agents,
                                                  const std::vector<double>& aggregates) {
  BayindirState state = all_searching(agents);
  for (int m = 2; m <= agents && m < static_cast<int>(aggregates.size()); ++m) {
    const double count = aggregates[static_cast<std::size_t>(m)];
    state.aggregates[static_cast<std::size_t>(m)] = count;
    state.searching -= m * count;
    state.totals.creations += count;
    state.totals.encounters += count;
    state.totals.growths += (m - 2) * count;
  }
  return state;
}

double BayindirState::noa() const {
  // Above the size bound every count is zero: adding them changes no bit of the sum.
  const auto end = size_bound
                       ? std::min(aggregates.size(), static_cast<std::size_t>(*size_bound) + 1)
                       : aggregates.size();
  return std::accumulate(aggregates.begin(), aggregates.begin() + static_cast<std::ptrdiff_t>(end),
                         0.0);
}

double BayindirState::agents_accounted() const {
  double total = searching;
  for (int m = 2; m <= agents(); ++m) total += m * aggregates[m];
  return total;
}

double BayindirState::largest_present() const {
  for (int m = std::min(agents(), size_bound.value_or(agents())); m >= 2; --m) {
    if (aggregates[m] > 0.0) return m;
  }
  return 0.0;
}

double BayindirState::largest_expected() const {
  double at_least = 0.0;
  for (int m = agents(); m >= 2; --m) {
    at_least += aggregates[m];
    if (at_least >= 0.5) return m;
  }
  return 0.0;
}

ModelRow to_model_row(const BayindirState& state, bool forms_aggregates, bool expected_counts,
                      int replicate, std::int64_t step) {
  ModelRow row;
  row.replicate = replicate;
  row.step = step;
  if (!forms_aggregates) {
    row.encounters = state.totals.encounters;
    return row;
  }
  row.noa = state.noa();
  row.searching = state.searching;
  row.waiting = state.agents() - state.searching;
  row.largest = expected_counts ? state.largest_expected() : state.largest_present();
  row.creations = state.totals.creations;
  row.growths = state.totals.growths;
  row.dissipations = state.totals.dissipations;
  row.shrinks = state.totals.shrinks;
  return row;
}

}  // namespace swarmagg
