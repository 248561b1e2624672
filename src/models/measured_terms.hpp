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
  // [m] LEAVE attempts per size-m aggregate per tu.
  std::map<int, double> attempt;
  // [m] the fraction of attempts from size m that return to the aggregate they left, and
  // [m] new joins (joins that are not returns) per searcher per size-m aggregate per tu.
  // The measured variant loses agents at attempt (1 - returned), at the attempt rate where a
  // size's return fraction was not measured. Once any return fraction is measured it grows
  // at new_growth, and at the model's growth where a size's new joins were too few to
  // measure: a return is no join. Without returns it grows at the whole growth rate.
  std::map<int, double> returned;
  std::map<int, double> new_growth;
};

}  // namespace swarmagg
