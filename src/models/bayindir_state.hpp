#pragma once
// The state of the Bayindir model: y searching agents, n_m aggregates of size m (m = 2..N)
// and the cumulative event counts. The expected-value model holds real expectations, the
// stochastic model whole numbers (exact in a double). Both conserve y + sum m n_m = N.
#include <cstdint>
#include <optional>
#include <vector>

#include "models/model_series.hpp"

namespace swarmagg {

struct EventTotals {
  double creations = 0.0, growths = 0.0, dissipations = 0.0, shrinks = 0.0, encounters = 0.0;
};

struct BayindirState {
  double searching = 0.0;
  std::vector<double> aggregates;  // [m] = n_m; indices 0 and 1 unused
  EventTotals totals;
  // When set, no aggregate is larger than this: the stochastic model keeps it after each
  // step, so that finding the largest aggregate does not search all N sizes. Whoever
  // changes `aggregates` otherwise leaves it unset.
  std::optional<int> size_bound;

  static BayindirState all_searching(int agents);
  // The state after a first decision that formed `aggregates` ([m]) from all searching:
  // each aggregate counted as a creation plus m - 2 growths, as the simulation counts them.
  static BayindirState after_first_decision(int agents, const std::vector<double>& aggregates);
  int agents() const { return static_cast<int>(aggregates.size()) - 1; }
  double noa() const;
  double agents_accounted() const;  // y + sum m n_m, equal to N when conserved
  // Largest size present (0 without aggregates): exact for whole-number states.
  double largest_present() const;
  // For expected counts: the largest m whose expected number of aggregates of size >= m is
  // at least 1/2 (0 if none), i.e. roughly the median of the largest aggregate.
  double largest_expected() const;
};

// A timeseries row of the state. Collision-controller worlds form no aggregates, so only
// their encounters are a prediction.
ModelRow to_model_row(const BayindirState& state, bool forms_aggregates, bool expected_counts,
                      int replicate, std::int64_t step);

}  // namespace swarmagg
