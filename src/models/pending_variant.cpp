#include "models/pending_variant.hpp"

namespace swarmagg {

VariantPrediction collect(const PendingVariant& pending) {
  VariantPrediction prediction = pending.header;
  prediction.extra = pending.walk_rows(
      [&](const ModelRow& row) { prediction.series.push_back(row); }, {}, Extras::Computed);
  return prediction;
}

}  // namespace swarmagg
