#include "reproduce/paper_predictions.hpp"

#include "controllers/controller_registry.hpp"
#include "models/predictions.hpp"

namespace swarmagg {

std::vector<PendingVariant> paper_predictions(const WorldSpec& world, const MeasuredTerms* measured,
                                              const PlacementSample* sample) {
  std::vector<PendingVariant> predictions = pending_predictions(world, measured, sample);
  if (controller_rules(world).model == ModelFamily::Soysal || world.model.kappa == Kappa::Paper) {
    return predictions;
  }
  WorldSpec fitted = world;
  fitted.model.kappa = Kappa::Paper;
  fitted.model.stochastic_replicates = 0;  // only its expected collision variant is kept
  for (PendingVariant& prediction : pending_predictions(fitted, measured, sample)) {
    if (prediction.header.model == "bayindir" && prediction.header.variant == "collision") {
      prediction.header.variant = kPaperFitVariant;
      prediction.header.chosen = false;
      predictions.push_back(std::move(prediction));
    }
  }
  return predictions;
}

}  // namespace swarmagg
