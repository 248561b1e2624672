#pragma once
// A finished run folder read back (docs/reference/outputs.md), so plots are drawn from the files a
// user can open, the same whether the run has just finished or ran long ago: the resolved world,
// timeseries.csv, summary.json and, when present, model.csv and partitions.csv.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "config/world_spec.hpp"

namespace swarmagg {

// timeseries.csv and model.csv grow with the run's length: they are named here and read row
// by row where used (analysis/step_series.hpp, analysis/model_table.hpp).
struct RunFiles {
  std::filesystem::path folder;
  WorldSpec world;
  std::filesystem::path timeseries;
  // What the plots read of summary.json, checked against the world when the folder is read.
  std::vector<std::vector<int>> final_sizes;   // each replicate's final aggregate sizes
  std::vector<std::string> overrides;          // "key=value", as the run was given them
  double wall_seconds = 0.0;                   // the run's wall time (0 when not recorded)
  std::optional<std::filesystem::path> model;  // model.csv, absent with --no-model
  bool has_partitions = false;                 // partitions.csv (Soysal worlds)
};

// Throws InputError naming the folder when it holds no complete run (world.resolved.yaml
// is written last, timeseries.csv before it), or naming the file and the key when a file is
// unreadable or summary.json does not fit the world (edited or damaged since).
RunFiles read_run_files(const std::filesystem::path& folder);

// Why `timeseries` is not every row of every replicate of `spec` (in order, at the recorded
// steps, counts that the world's agents can have, ending with a whole line), or nothing: a
// file cut short, or edited by hand, describes another run than the folder's other files.
std::optional<std::string> timeseries_problem(const WorldSpec& spec,
                                              const std::filesystem::path& timeseries);
bool holds_every_row(const WorldSpec& spec, const std::filesystem::path& timeseries);
// Throws InputError naming the file unless it holds_every_row: for a stored run read back
// (`plot`), not for the outputs a run has just written, which would only be read twice.
void check_holds_every_row(const RunFiles& run);

// The world's name for plot titles, followed by the overrides the run was given, if any:
// "full-0.0025 (robots.count=80)".
std::string run_title(const RunFiles& run);

}  // namespace swarmagg
