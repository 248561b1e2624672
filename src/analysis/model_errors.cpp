#include "analysis/model_errors.hpp"

#include <algorithm>
#include <fstream>
#include <functional>

#include "analysis/csv_reader.hpp"
#include "analysis/noa_error.hpp"
#include "analysis/partition_comparison.hpp"
#include "core/errors.hpp"
#include "models/noise_floor.hpp"
#include "output/atomic_file.hpp"

namespace swarmagg {

namespace {

constexpr const char* kStochasticSuffix = "-stochastic";

std::vector<ModelError> noa_errors(const std::filesystem::path& folder) {
  const std::map<std::string, double> floors =
      read_noise_floors(folder / "model.csv", "bayindir", kNoaMetric);
  std::vector<std::string> variants;
  const std::filesystem::path series = folder / "model-timeseries";
  if (!std::filesystem::is_directory(series)) return {};
  for (const auto& entry : std::filesystem::directory_iterator(series)) {
    const std::string name = entry.path().stem().string();
    if (!name.starts_with("bayindir-") || name.ends_with(kStochasticSuffix)) continue;
    variants.push_back(name.substr(std::string("bayindir-").size()));
  }
  std::sort(variants.begin(), variants.end());
  const std::vector<StepMean> simulation = read_noa_means(folder / "timeseries.csv");
  std::vector<ModelError> errors;
  for (const std::string& variant : variants) {
    const std::vector<StepMean> predicted =
        read_noa_means(series / ("bayindir-" + variant + ".csv"));
    if (predicted.empty()) continue;
    const auto floor = floors.find(variant);
    errors.push_back({kNoaMetric,
                      {variant, noa_rmse(simulation, predicted),
                       floor == floors.end() ? std::nullopt : std::optional(floor->second)}});
  }
  return errors;
}

}  // namespace

std::map<std::string, double> read_noise_floors(const std::filesystem::path& model_csv,
                                                const std::string& model,
                                                const std::string& metric) {
  CsvReader csv(model_csv);
  const std::size_t name = csv.column("model"), variant = csv.column("variant"),
                    quantity = csv.column("quantity"), value = csv.column("value");
  const std::string wanted = std::string(kNoiseFloorQuantity) + metric;
  std::map<std::string, double> floors;
  while (csv.next()) {
    if (csv.cell(name) == model && csv.cell(quantity) == wanted)
      floors[csv.cell(variant)] = csv.number(value);
  }
  return floors;
}

std::vector<ModelError> run_model_errors(const std::filesystem::path& run_folder) {
  if (!std::filesystem::exists(run_folder / "model.csv")) return {};
  if (std::filesystem::exists(run_folder / "partitions.csv")) {
    std::vector<ModelError> errors;
    for (const VariantError& e : compare_partitions(run_folder).errors)
      errors.push_back({kPartitionMetric, e});
    return errors;
  }
  return noa_errors(run_folder);
}

nlohmann::json model_errors_json(const std::vector<ModelError>& errors) {
  nlohmann::json list = nlohmann::json::array();
  for (const ModelError& e : errors) {
    list.push_back({{"variant", e.error.variant},
                    {"metric", e.metric},
                    {"value", e.error.error},
                    {"noise_floor", e.error.noise_floor ? nlohmann::json(*e.error.noise_floor)
                                                        : nlohmann::json(nullptr)}});
  }
  return list;
}

namespace {

// summary.json rewritten with `change` applied; InputError when it is no JSON object.
void rewrite_summary(const std::filesystem::path& run_folder,
                     const std::function<void(nlohmann::json&)>& change) {
  const std::filesystem::path file = run_folder / "summary.json";
  nlohmann::json summary;
  {
    std::ifstream in(file);
    summary = nlohmann::json::parse(in, nullptr, false);
  }
  if (!summary.is_object()) throw InputError(file.string() + ": not a run's summary (JSON object)");
  change(summary);
  write_file_atomic(file, summary.dump(2) + "\n");
}

}  // namespace

void write_model_errors(const std::filesystem::path& run_folder) {
  const nlohmann::json errors = model_errors_json(run_model_errors(run_folder));
  rewrite_summary(run_folder, [&](nlohmann::json& summary) { summary["model_errors"] = errors; });
}

void remove_model_errors(const std::filesystem::path& run_folder) {
  rewrite_summary(run_folder, [](nlohmann::json& summary) { summary.erase("model_errors"); });
}

}  // namespace swarmagg
