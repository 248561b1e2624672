#include "reproduce/encounter_comparison.hpp"

#include <cmath>
#include <map>

#include "analysis/csv_reader.hpp"
#include "models/kinetic_rate.hpp"
#include "models/sample_statistics.hpp"

namespace swarmagg {

EncounterPoint measure_encounters(const WorldSpec& world, const std::filesystem::path& run_folder) {
  CsvReader table(run_folder / "timeseries.csv");
  const std::size_t replicate = table.column("replicate"), time = table.column("time"),
                    encounters = table.column("encounters");
  // Rows are in step order per replicate, so the last row seen is the final one.
  std::map<std::string, double> rate;
  while (table.next()) {
    const double t = table.number(time);
    if (t > 0.0) rate[table.cell(replicate)] = table.number(encounters) / t;
  }
  std::vector<double> rates;
  for (const auto& [r, value] : rate) rates.push_back(value);
  const double s = world.robots.detection_radius, v = world.robots.speed, area = world.arena.area();
  const int n = world.robots.count;
  return {n,
          v,
          sample_mean(rates),
          sample_sd(rates),
          encounter_rate(Kappa::Kinetic, s, v, area).at(n),
          encounter_rate(Kappa::Paper, s, v, area).at(n)};
}

}  // namespace swarmagg
