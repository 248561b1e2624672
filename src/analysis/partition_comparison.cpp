#include "analysis/partition_comparison.hpp"

#include <cmath>
#include <set>

#include "analysis/csv_reader.hpp"
#include "analysis/csv_table.hpp"
#include "analysis/model_errors.hpp"
#include "analysis/replicate_spread.hpp"
#include "models/noise_floor.hpp"
#include "models/return_probability.hpp"
#include "models/soysal_model.hpp"

namespace swarmagg {
namespace {

constexpr const char* kTransient = "partition:";
constexpr const char* kStationary = "stationary:";

// partition -> (time, probability) points of one variant, in file order (increasing time).
using Trajectories = std::map<std::string, std::vector<std::pair<double, double>>>;

Distribution run_average(const Trajectories& trajectories) {
  Distribution average;
  for (const auto& [partition, points] : trajectories) {
    double area = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
      area +=
          0.5 * (points[i].second + points[i - 1].second) * (points[i].first - points[i - 1].first);
    }
    const double span = points.back().first - points.front().first;
    average[partition] = span > 0.0 ? area / span : points.back().second;
  }
  return average;
}

}  // namespace

const std::vector<std::string>& partition_variants() {
  static const std::vector<std::string> variants{"original", "peripheral"};
  return variants;
}

double total_variation(const Distribution& a, const Distribution& b) {
  std::set<std::string> keys;
  for (const auto& [k, v] : a) keys.insert(k);
  for (const auto& [k, v] : b) keys.insert(k);
  double sum = 0.0;
  for (const std::string& key : keys) {
    const auto in_a = a.find(key), in_b = b.find(key);
    sum +=
        std::abs((in_a == a.end() ? 0.0 : in_a->second) - (in_b == b.end() ? 0.0 : in_b->second));
  }
  return 0.5 * sum;
}

std::vector<Distribution> replicate_partitions(const std::filesystem::path& partitions_csv) {
  const CsvTable table = read_csv(partitions_csv);
  const std::size_t replicate = table.column("replicate"), partition = table.column("partition"),
                    fraction = table.column("time_fraction");
  std::map<double, Distribution> by_replicate;  // indices as numbers: 10 after 9
  for (std::size_t row = 0; row < table.rows.size(); ++row)
    by_replicate[table.number(row, replicate)][table.rows[row][partition]] +=
        table.number(row, fraction);
  std::vector<Distribution> replicates;
  for (auto& [index, distribution] : by_replicate) replicates.push_back(std::move(distribution));
  return replicates;
}

// Summed replicate by replicate, as partitions.csv lists them: the same sums, bit for bit, as
// its rows added in file order.
Distribution mean_partitions(const std::vector<Distribution>& replicates) {
  Distribution sums;
  for (const Distribution& replicate : replicates) {
    for (const auto& [partition, fraction] : replicate) sums[partition] += fraction;
  }
  for (auto& [key, value] : sums) value /= static_cast<double>(replicates.size());
  return sums;
}

PartitionComparison compare_partitions(const std::filesystem::path& run_folder) {
  PartitionComparison comparison;
  const std::vector<Distribution> replicates = replicate_partitions(run_folder / "partitions.csv");
  comparison.simulation = mean_partitions(replicates);
  comparison.spread = partition_spread(replicates);
  // A run without predictions (--no-model, or too many agents for the chain) has only its own.
  if (!std::filesystem::exists(run_folder / "model.csv")) return comparison;
  CsvReader model(run_folder / "model.csv");
  const std::size_t name = model.column("model"), variant = model.column("variant"),
                    time = model.column("time"), quantity = model.column("quantity"),
                    value = model.column("value");
  std::map<std::string, Trajectories> transient;
  std::map<std::string, Distribution> stationary;
  std::map<std::string, Distribution> averaged;  // the model's own run averages
  while (model.next()) {
    if (model.cell(name) != "soysal") continue;
    const std::string& q = model.cell(quantity);
    if (q.starts_with(kRunAverageQuantity)) {
      averaged[model.cell(variant)][q.substr(std::string(kRunAverageQuantity).size())] =
          model.number(value);
    } else if (q.starts_with(kTransient)) {
      transient[model.cell(variant)][q.substr(std::string(kTransient).size())].emplace_back(
          model.number(time), model.number(value));
    } else if (q.starts_with(kStationary)) {
      stationary[model.cell(variant)][q.substr(std::string(kStationary).size())] =
          model.number(value);
    }
  }
  std::vector<std::string> variants = partition_variants();
  // Worlds whose aggregates lose agents have the returns variant; a run that measured its
  // rates (run --rates, reproduce) also has the measured variant.
  for (const char* extra : {kReturnsVariant, kMeasuredVariant}) {
    if (transient.contains(extra)) variants.push_back(extra);
  }
  const std::map<std::string, double> floors =
      read_noise_floors(run_folder / "model.csv", "soysal", kPartitionMetric);
  for (const std::string& v : variants) {
    // A model.csv written before the model averaged its run itself has only the report
    // steps, which a large run.record_every spaces out.
    comparison.models.push_back(averaged.contains(v) ? averaged.at(v)
                                                     : run_average(transient.at(v)));
    comparison.stationary.push_back(stationary[v]);
    const auto floor = floors.find(v);
    comparison.errors.push_back(
        {v, total_variation(comparison.simulation, comparison.models.back()),
         floor == floors.end() ? std::nullopt : std::optional(floor->second)});
  }
  return comparison;
}

}  // namespace swarmagg
