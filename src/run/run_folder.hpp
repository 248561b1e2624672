#pragma once
// The run output folder (docs/reference/outputs.md): world.resolved.yaml, timeseries.csv,
// summary.json and, for Soysal worlds, partitions.csv; each written atomically.
#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "config/world_spec.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {

// The resolved world with the swarmagg version and every replicate's seed as comments; it
// loads back as the same world.
std::string resolved_world_text(const WorldSpec& spec);
// `overrides` ("robots.count=80") name what the command line changed of the world file, so
// the summary and the plot titles do not pass an overridden run off as the file's world.
nlohmann::json run_summary(const WorldSpec& spec, const RunResult& result,
                           const std::vector<std::string>& overrides = {});
std::string partitions_csv(const RunResult& result, std::int64_t steps);
std::vector<TimeseriesRow> all_rows(const RunResult& result);

// `timeseries`: the spool the run's rows went to (run/timeseries_spool.hpp), committed as
// out/timeseries.csv; none: the rows of `result` are written.
void write_run_folder(const WorldSpec& spec, const RunResult& result,
                      const std::filesystem::path& out,
                      const std::vector<std::string>& overrides = {},
                      TimeseriesSpool* timeseries = nullptr);

// Whether `folder` holds a complete run: its world.resolved.yaml, summary.json and timeseries.csv.
bool holds_complete_run(const std::filesystem::path& folder);
// The text of the folder's world.resolved.yaml; InputError when it cannot be read.
std::string resolved_world_in(const std::filesystem::path& folder);

// runs/<world name> unless --out says otherwise.
std::filesystem::path default_run_folder(const WorldSpec& spec);

}  // namespace swarmagg
