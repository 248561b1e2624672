#pragma once
// Model terms measured by a simulation (docs/models.md), in the units the rates outputs use: per
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
  // [m] LEAVE attempts per size-m aggregate per tu. The measured variant loses agents at this
  // rate, not at the escape rate: an attempt that does not escape comes back as a growth
  // (join), which the measured growth rate already counts.
  std::map<int, double> attempt;
};

}  // namespace swarmagg
