#pragma once
// A model variant whose rows are computed while its outputs are written, not held: a long
// prediction's rows (every recorded step, times the replicates of a stochastic variant) do
// not fit in memory (10^7 steps of the demo world took 11.6 GB). A walk computes the rows
// from the variant's rates and start, which the variant holds, in the order one output
// needs; each walk computes them again.
#include <functional>
#include <span>
#include <vector>

#include "models/model_series.hpp"
#include "models/output_grid.hpp"

namespace swarmagg {

using RowVisitor = std::function<void(const ModelRow& row)>;
// Whether a walk of the rows also computes the extra values: the noise floor alone walks the
// series again for every replicate of 20 batches, and a live view wants the rows only.
enum class Extras { Computed, Skipped };
// Every replicate's row at one step, in replicate order.
using StepVisitor = std::function<void(std::span<const ModelRow> rows)>;

struct PendingVariant {
  // model, variant, stochastic and chosen; no rows and no extra values.
  VariantPrediction header;
  // Hands `visit` the rows in model-timeseries order (replicate by replicate, each step by
  // step) and returns the extra values, which need the whole walk (the size distribution at
  // the last step, the noise floor), or none when Skipped.
  std::function<std::vector<TidyValue>(const RowVisitor& visit, const WalkProgress& progress,
                                       Extras extras)>
      walk_rows = {};
  // Stochastic variants: hands `visit` the rows step by step, for model.csv's statistics over
  // the replicates. The replicates run side by side, with the draws walk_rows makes.
  std::function<void(const StepVisitor& visit, const WalkProgress& progress)> walk_steps = {};
  // The model steps each walk reports to its progress in all (replicates' steps add up).
  double walk_rows_work = 0.0;
  double walk_steps_work = 0.0;
};

// The variant with every row and extra value, held (what predict() gives).
VariantPrediction collect(const PendingVariant& pending);

}  // namespace swarmagg
