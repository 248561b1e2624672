#include "analysis/run_files.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
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

[[noreturn]] void refuse_summary(const std::filesystem::path& file, const std::string& key,
                                 const std::string& expected) {
  throw InputError(file.string() + ": " + key + ": expected " + expected +
                   "; the file was edited or damaged since the run: run the world again");
}

// Each replicate's final aggregate sizes: whole numbers from 2 to N, N at most in all.
std::vector<int> final_sizes_of(const nlohmann::json& replicate, const std::string& key,
                                const std::filesystem::path& file, int agents) {
  const std::string expected = "a list of aggregate sizes, whole numbers from 2 to " +
                               std::to_string(agents) +
                               " (the world's robots.count) that add up to at most that";
  if (!replicate.is_object() || !replicate.contains("final") || !replicate["final"].is_object() ||
      !replicate["final"].contains("aggregate_sizes") ||
      !replicate["final"]["aggregate_sizes"].is_array())
    refuse_summary(file, key, expected);
  std::vector<int> sizes;
  std::int64_t total = 0;
  for (const nlohmann::json& size : replicate["final"]["aggregate_sizes"]) {
    if (!size.is_number_integer() || size.get<std::int64_t>() < 2 ||
        size.get<std::int64_t>() > agents)
      refuse_summary(file, key, expected + ", got " + size.dump());
    sizes.push_back(size.get<int>());
    total += sizes.back();
  }
  if (total > agents) refuse_summary(file, key, expected + ", got " + std::to_string(total));
  return sizes;
}

// What the plots read of summary.json: each replicate's final sizes and the overrides.
void read_summary(const std::filesystem::path& file, RunFiles& run) {
  const nlohmann::json summary = read_json(file);
  const int replicates = run.world.run.replicates;
  if (!summary.is_object() || !summary.contains("replicates") ||
      !summary["replicates"].is_array() ||
      summary["replicates"].size() != static_cast<std::size_t>(replicates))
    refuse_summary(file, "replicates",
                   "a list of " + std::to_string(replicates) + " (the world's run.replicates)");
  for (std::size_t i = 0; i < summary["replicates"].size(); ++i) {
    run.final_sizes.push_back(final_sizes_of(
        summary["replicates"][i], "replicates[" + std::to_string(i) + "].final.aggregate_sizes",
        file, run.world.robots.count));
  }
  if (summary.contains("wall_seconds") && summary["wall_seconds"].is_number())
    run.wall_seconds = summary["wall_seconds"].get<double>();
  if (!summary.contains("overrides")) return;
  const nlohmann::json& overrides = summary["overrides"];
  const bool texts =
      overrides.is_array() && std::all_of(overrides.begin(), overrides.end(),
                                          [](const nlohmann::json& o) { return o.is_string(); });
  if (!texts) refuse_summary(file, "overrides", "a list of texts (key=value)");
  for (const nlohmann::json& o : overrides) run.overrides.push_back(o.get<std::string>());
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
  read_summary(folder / "summary.json", run);
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
  std::string changed;
  for (const std::string& assignment : run.overrides) {
    changed += (changed.empty() ? "" : ", ") + assignment;
  }
  return changed.empty() ? run.world.name : run.world.name + " (" + changed + ")";
}

}  // namespace swarmagg
