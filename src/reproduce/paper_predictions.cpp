#include "reproduce/paper_predictions.hpp"

#include "controllers/controller_registry.hpp"
#include "models/predictions.hpp"

namespace swarmagg {

std::vector<VariantPrediction> paper_predictions(const WorldSpec& world,
                                                 const MeasuredTerms* measured,
                                                 const PlacementSample* sample) {
  std::vector<VariantPrediction> predictions = predict(world, measured, sample);
  if (controller_rules(world).model == ModelFamily::Soysal || world.model.kappa == Kappa::Paper) {
    return predictions;
  }
  WorldSpec fitted = world;
  fitted.model.kappa = Kappa::Paper;
  fitted.model.stochastic_replicates = 0;  // only its expected collision variant is kept
  for (VariantPrediction& prediction : predict(fitted, measured, sample)) {
    if (prediction.model == "bayindir" && prediction.variant == "collision") {
      prediction.variant = kPaperFitVariant;
      prediction.chosen = false;
      predictions.push_back(std::move(prediction));
    }
  }
  return predictions;
}

}  // namespace swarmagg
