#pragma once
// Model terms measured by a simulation (SPEC 5.4), in the units the rates outputs use: per
// tu, per searcher pair or per (searcher, aggregate) pair. A term that is absent was not
// measured (too few events, or the world has no such event) and the measured variant falls
// back to the model's own term for it.
#include <map>
#include <optional>

namespace swarmagg {

struct MeasuredTerms {
  std::optional<double> creation;  // creations (Soysal: pair-ups) per searcher pair per tu
  std::map<int, double>
      growth;  // [m] growths (Soysal: joins) per searcher per size-m aggregate per tu
  // [m] mean number of aggregates of size m after the first decision (the placement pairs).
  std::map<int, double> initial;
  // Leave attempts and escapes per size-m aggregate per tu join here once the compaction
  // issue's leave episodes are observed (their exposure, sum n_m dt, is already tallied as
  // RateTally::aggregate_steps); measured_bayindir_rates / measured_soysal_rates would then
  // replace the model's loss / leave terms by the escape rates.
};

}  // namespace swarmagg
