#include "analysis/run_files.hpp"

#include <algorithm>
#include <fstream>
#include <vector>

#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "run/recorded_steps.hpp"

namespace swarmagg {
namespace {

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot read the run's summary");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace

RunFiles read_run_files(const std::filesystem::path& folder) {
  const auto resolved = folder / "world.resolved.yaml";
  if (!std::filesystem::is_directory(folder))
    throw InputError(folder.string() + ": no such folder (expected a run's output folder)");
  if (!std::filesystem::exists(resolved)) {
    throw InputError(folder.string() +
                     ": holds no complete run (no world.resolved.yaml, which a run writes once its "
                     "simulation's outputs are complete)");
  }
  RunFiles run;
  run.folder = folder;
  run.world = load_world(resolved.string());
  run.timeseries = folder / "timeseries.csv";
  if (!std::filesystem::is_regular_file(run.timeseries))
    throw InputError("cannot read " + run.timeseries.string());
  run.summary = read_json(folder / "summary.json");
  if (std::filesystem::exists(folder / "model.csv")) run.model = folder / "model.csv";
  run.has_partitions = std::filesystem::exists(folder / "partitions.csv");
  return run;
}

bool holds_every_row(const WorldSpec& spec, const std::filesystem::path& timeseries) {
  std::ifstream in(timeseries, std::ios::binary);
  if (!in) return false;
  std::int64_t lines = 0;
  char last = '\n';
  std::vector<char> block(std::size_t{1} << 16);  // a long run's file is gigabytes
  while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0) {
    const auto read = static_cast<std::size_t>(in.gcount());
    lines += std::count(block.data(), block.data() + read, '\n');
    last = block[read - 1];
  }
  return last == '\n' && lines == 1 + spec.run.replicates * recorded_rows(spec);
}

void check_holds_every_row(const RunFiles& run) {
  if (holds_every_row(run.world, run.timeseries)) return;
  throw InputError(run.timeseries.string() + ": does not hold exactly the run's rows (" +
                   std::to_string(run.world.run.replicates) + " replicates of " +
                   std::to_string(recorded_rows(run.world)) +
                   " rows each, the last ending its line): cut short or edited since; run the "
                   "world again");
}

std::string run_title(const RunFiles& run) {
  std::string title = run.world.name;
  const auto overrides = run.summary.find("overrides");
  if (overrides == run.summary.end() || !overrides->is_array() || overrides->empty()) return title;
  std::string changed;
  for (const auto& assignment : *overrides) {
    changed += (changed.empty() ? "" : ", ") + assignment.get<std::string>();
  }
  return title + " (" + changed + ")";
}

std::vector<std::vector<int>> final_aggregate_sizes(const RunFiles& run) {
  std::vector<std::vector<int>> sizes;
  for (const auto& replicate : run.summary.at("replicates")) {
    sizes.push_back(replicate.at("final").at("aggregate_sizes").get<std::vector<int>>());
  }
  return sizes;
}

}  // namespace swarmagg
