#include "run/model_outputs.hpp"

#include <fstream>
#include <set>
#include <string>
#include <system_error>

#include "models/model_csv.hpp"
#include "output/atomic_file.hpp"

namespace swarmagg {

namespace {

// The variant files of the model.csv in `out` (model-timeseries/<model>-<variant>.csv), read
// leniently: the file may be damaged or of another version.
std::set<std::string> earlier_variant_files(const std::filesystem::path& out) {
  std::set<std::string> files;
  std::ifstream in(out / "model.csv");
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    const std::size_t model_end = line.find(',');
    if (model_end == std::string::npos) continue;
    const std::size_t variant_end = line.find(',', model_end + 1);
    if (variant_end == std::string::npos) continue;
    const std::string file = line.substr(0, model_end) + "-" +
                             line.substr(model_end + 1, variant_end - model_end - 1) + ".csv";
    // A name that is not one file of model-timeseries/ is no variant of ours.
    if (file.find('/') == std::string::npos && !file.starts_with(".")) files.insert(file);
  }
  return files;
}

}  // namespace

void write_model_outputs(const WorldSpec& spec, const std::vector<VariantPrediction>& predictions,
                         const std::filesystem::path& out) {
  const std::filesystem::path series = out / "model-timeseries";
  std::filesystem::create_directories(series);
  std::set<std::string> stale = earlier_variant_files(out);
  write_file_atomic(out / "model.csv", model_csv(predictions, spec.engine.dt));
  for (const VariantPrediction& prediction : predictions) {
    const std::string file = prediction.model + "-" + prediction.variant + ".csv";
    write_file_atomic(series / file, model_timeseries_csv(prediction, spec.engine.dt));
    stale.erase(file);
  }
  // A variant the earlier model of the folder had (`measured`, say) would stay beside these;
  // files of yours in model-timeseries/ stay.
  std::error_code error;
  for (const std::string& file : stale) std::filesystem::remove(series / file, error);
}

}  // namespace swarmagg
