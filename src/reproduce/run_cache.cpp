#include "reproduce/run_cache.hpp"

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/model_errors.hpp"
#include "analysis/run_files.hpp"
#include "config/world_difference.hpp"
#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "rates/rate_outputs.hpp"
#include "reproduce/paper_predictions.hpp"
#include "run/earlier_run.hpp"
#include "run/measured_run.hpp"
#include "run/model_outputs.hpp"
#include "run/partition_recording.hpp"
#include "run/placement_sample.hpp"
#include "run/run_folder.hpp"

namespace swarmagg {
namespace {

std::string text_of(std::istream& in) {
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// summary.json gains its model errors after world.resolved.yaml marked the folder complete
// (they are read from the folder's files), so a run stopped in between is not reused.
bool holds_model_errors(const std::filesystem::path& summary_file) {
  std::ifstream in(summary_file);
  const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
  return summary.is_object() && summary.contains("model_errors");
}

// What reproduce changed in the paper world's file (--quick's length, --set, the compaction-off
// arm, a timeout of the series), for summary.json's overrides as `run --set` records them.
std::vector<std::string> changes_to_its_file(const WorldSpec& spec) {
  try {
    return changed_keys(load_world(spec.source), spec);
  } catch (const InputError&) {
    return {};  // not from a file (a test's world)
  }
}

}  // namespace

bool run_is_reusable(const WorldSpec& spec, const std::filesystem::path& folder) {
  std::ifstream resolved(folder / "world.resolved.yaml");
  if (!resolved || !std::filesystem::exists(folder / "model.csv") ||
      !std::filesystem::exists(folder / "rates.csv") ||
      (records_partitions(spec) && !std::filesystem::exists(folder / "partitions.csv"))) {
    return false;
  }
  // The whole text, comments included: its first line names the swarmagg version and commit
  // that made the run, and a run made by another build of the same world need not give the
  // same outputs (a fix in an engine moves them).
  // The rows last: reading them all costs the most.
  return text_of(resolved) == resolved_world_text(spec) &&
         holds_model_errors(folder / "summary.json") &&
         holds_every_row(spec, folder / "timeseries.csv");
}

bool ensure_run(const WorldSpec& spec, const std::filesystem::path& folder,
                const RunOptions& options, RatePlots rate_plots) {
  if (run_is_reusable(spec, folder)) return true;
  std::filesystem::remove(folder / "world.resolved.yaml");
  // The run measures the model terms as it goes; the measured variants need them, so the
  // models follow the run, and world.resolved.yaml, written last by write_run_folder, marks
  // the folder complete with the rates and model outputs beside it.
  const MeasuredRun run = run_world_measuring(spec, options, true);
  const std::optional<PlacementSample> start = placement_start(spec, options.threads);
  const PlacementSample* sample = start ? &*start : nullptr;
  const std::vector<RateRow> rows = measured_rate_rows(spec, *run.rates, sample);
  // An earlier reproduction's rate plots (drawn with --run-plots) would stay beside the new
  // rates, whose scripts alone are written by default.
  std::vector<std::string> failures;
  clear_earlier_rates(folder, failures);
  for (const std::string& failure : failures)
    std::cerr << "warning: cannot remove the earlier rates' " << failure << "\n";
  write_rate_outputs(spec, *run.rates, rows, folder, rate_plots);
  const MeasuredTerms terms = measured_terms(rows);
  write_model_outputs(spec, paper_predictions(spec, &terms, sample), folder);
  write_run_folder(spec, run.result, folder, changes_to_its_file(spec));
  write_model_errors(folder);
  return false;
}

}  // namespace swarmagg
