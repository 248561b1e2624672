#include "analysis/run_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/csv_reader.hpp"
#include "analysis/csv_text.hpp"
#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "models/output_grid.hpp"
#include "output/timeseries_csv.hpp"
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

namespace {

// The timeseries.csv columns of counts: at most the world's agents (NOA at most half of them).
constexpr std::size_t kFirstCount = 3, kFirstEvent = 9;

// Why row `row` (replicate-major, as a run writes them) is not the run's, or "".
std::string row_problem(const CsvReader& reader, const WorldSpec& spec,
                        const std::vector<std::int64_t>& grid, std::int64_t row) {
  const auto rows = static_cast<std::int64_t>(grid.size());
  if (row >= spec.run.replicates * rows) return "a row after the last replicate's last state";
  const std::int64_t replicate = row / rows, step = grid[static_cast<std::size_t>(row % rows)];
  if (reader.number(0) != static_cast<double>(replicate) ||
      reader.number(1) != static_cast<double>(step)) {
    return "expected replicate " + std::to_string(replicate) + " at step " + std::to_string(step) +
           " (every " + std::to_string(spec.run.record_every) +
           " steps and the last), got replicate " + reader.cell(0) + " at step " + reader.cell(1);
  }
  if (!std::isfinite(reader.number(2)))
    return "time: expected a number, got '" + reader.cell(2) + "'";
  const double agents = spec.robots.count;
  for (std::size_t column = kFirstCount; column < reader.header().size(); ++column) {
    const double value = reader.number(column);
    const double most = column >= kFirstEvent              ? std::numeric_limits<double>::max()
                        : reader.header()[column] == "noa" ? std::floor(agents / 2)
                                                           : agents;
    if (std::isfinite(value) && value >= 0 && value <= most && value == std::floor(value)) continue;
    return reader.header()[column] + ": expected a whole number " +
           (column >= kFirstEvent ? std::string("of events, 0 or more")
                                  : "from 0 to " + csv_number(most) + " (the world has " +
                                        csv_number(agents) + " agents)") +
           ", got '" + reader.cell(column) + "'";
  }
  return "";
}

bool ends_with_newline(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in.seekg(-1, std::ios::end)) return false;
  return in.get() == '\n';
}

}  // namespace

std::optional<std::string> timeseries_problem(const WorldSpec& spec,
                                              const std::filesystem::path& timeseries) {
  try {
    CsvReader reader(timeseries);
    std::string header;
    for (const std::string& column : reader.header())
      header += (header.empty() ? "" : ",") + column;
    if (header != kTimeseriesHeader)
      return "expected the header '" + std::string(kTimeseriesHeader) + "'";
    const std::vector<std::int64_t> grid = record_grid(spec);
    std::int64_t row = 0;
    while (reader.next()) {
      const std::string problem = row_problem(reader, spec, grid, row++);
      if (!problem.empty()) return "line " + std::to_string(reader.line()) + ": " + problem;
    }
    if (row != spec.run.replicates * static_cast<std::int64_t>(grid.size()) ||
        !ends_with_newline(timeseries)) {
      return "does not hold exactly the run's rows (" + std::to_string(spec.run.replicates) +
             " replicates of " + std::to_string(grid.size()) +
             " rows each, the last ending its line)";
    }
    return std::nullopt;
  } catch (const InputError& e) {
    return std::string(e.what());
  }
}

bool holds_every_row(const WorldSpec& spec, const std::filesystem::path& timeseries) {
  return !timeseries_problem(spec, timeseries);
}

void check_holds_every_row(const RunFiles& run) {
  const std::optional<std::string> problem = timeseries_problem(run.world, run.timeseries);
  if (!problem) return;
  const std::string text = problem->starts_with(run.timeseries.string())
                               ? *problem
                               : run.timeseries.string() + ": " + *problem;
  throw InputError(text + ": cut short or edited since; run the world again");
}

std::string run_title(const RunFiles& run) {
  std::string changed;
  for (const std::string& assignment : run.overrides) {
    changed += (changed.empty() ? "" : ", ") + assignment;
  }
  return changed.empty() ? run.world.name : run.world.name + " (" + changed + ")";
}

}  // namespace swarmagg
