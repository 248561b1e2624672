#include "run/model_outputs.hpp"

#include <set>
#include <system_error>

#include "models/model_csv.hpp"
#include "output/atomic_file.hpp"

namespace swarmagg {

void write_model_outputs(const WorldSpec& spec, const std::vector<VariantPrediction>& predictions,
                         const std::filesystem::path& out) {
  const std::filesystem::path series = out / "model-timeseries";
  std::filesystem::create_directories(series);
  write_file_atomic(out / "model.csv", model_csv(predictions, spec.engine.dt));
  std::set<std::filesystem::path> written;
  for (const VariantPrediction& prediction : predictions) {
    const std::filesystem::path file =
        series / (prediction.model + "-" + prediction.variant + ".csv");
    write_file_atomic(file, model_timeseries_csv(prediction, spec.engine.dt));
    written.insert(file);
  }
  // A variant an earlier model of the folder had (`measured`, say) would stay beside these.
  std::vector<std::filesystem::path> stale;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(series, error)) {
    if (entry.path().extension() == ".csv" && !written.contains(entry.path()))
      stale.push_back(entry.path());
  }
  for (const std::filesystem::path& file : stale) std::filesystem::remove(file, error);
}

}  // namespace swarmagg
