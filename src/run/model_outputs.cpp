#include "run/model_outputs.hpp"

#include "models/model_csv.hpp"
#include "output/atomic_file.hpp"

namespace swarmagg {

void write_model_outputs(const WorldSpec& spec, const std::vector<VariantPrediction>& predictions,
                         const std::filesystem::path& out) {
  std::filesystem::create_directories(out / "model-timeseries");
  write_file_atomic(out / "model.csv", model_csv(predictions, spec.engine.dt));
  for (const VariantPrediction& prediction : predictions) {
    write_file_atomic(
        out / "model-timeseries" / (prediction.model + "-" + prediction.variant + ".csv"),
        model_timeseries_csv(prediction, spec.engine.dt));
  }
}

}  // namespace swarmagg
