#include "run/run_folder.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "config/world_keys.hpp"
#include "config/world_writer.hpp"
#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "core/rng.hpp"
#include "output/atomic_file.hpp"
#include "output/timeseries_csv.hpp"
#include "run/aggregate_summary.hpp"
#include "run/partition_recording.hpp"
#include "run/state_hash.hpp"
#include "run/timeseries_spool.hpp"
#include "swarmagg_version.hpp"

namespace swarmagg {
namespace {

nlohmann::json spread(const std::vector<double>& values) {
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  double squares = 0.0;
  for (double v : values) squares += (v - mean) * (v - mean);
  const double sd =
      values.size() > 1 ? std::sqrt(squares / static_cast<double>(values.size() - 1)) : 0.0;
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return {{"mean", mean}, {"sd", sd}, {"min", *low}, {"max", *high}};
}

nlohmann::json replicate_summary(const ReplicateOutcome& r, double dt) {
  const TimeseriesRow& last = r.final_row;
  nlohmann::json summary = {{"replicate", r.index},
                            {"seed", r.seed},
                            {"final_state_hash", state_hash_text(r.final_state_hash)},
                            {"wall_seconds", r.wall_seconds},
                            {"final",
                             {{"step", last.step},
                              {"time", last.time},
                              {"noa", last.noa},
                              {"searching", last.states.searching},
                              {"waiting", last.states.waiting},
                              {"leaving", last.states.leaving},
                              {"approaching", last.states.approaching},
                              {"largest", last.largest},
                              {"aggregate_sizes", r.final_aggregate_sizes}}},
                            {"events",
                             {{"creations", last.events.creations},
                              {"growths", last.events.growths},
                              {"dissipations", last.events.dissipations},
                              {"shrinks", last.events.shrinks},
                              {"encounters", last.events.encounters}}}};
  add_aggregate_entries(summary, r.leave, r.final_aggregates, dt);
  return summary;
}

// A replicate at a time: a long run's rows make gigabytes of text.
void write_timeseries_csv(const std::filesystem::path& file, const RunResult& result) {
  AtomicFileWriter csv(file);
  csv.write(std::string(kTimeseriesHeader) + "\n");
  for (const ReplicateOutcome& r : result.replicates) csv.write(timeseries_csv_lines(r.rows));
  csv.commit();
}

}  // namespace

std::string resolved_world_text(const WorldSpec& spec) {
  std::string text =
      "# Resolved by swarmagg " SWARMAGG_VERSION " (" SWARMAGG_GIT_HASH "); every key is shown.\n";
  text += "# Replicate k draws from the generator keyed by (run.seed, k):";
  for (int k = 0; k < spec.run.replicates && k < 1000; ++k) {
    text += (k % 4 == 0 ? "\n#  " : "  ") + std::to_string(k) + ": " +
            std::to_string(CounterRng::for_replicate(spec.run.seed, k).key());
  }
  return text + "\n" + world_to_yaml(spec);
}

std::vector<TimeseriesRow> all_rows(const RunResult& result) {
  std::vector<TimeseriesRow> rows;
  for (const ReplicateOutcome& r : result.replicates)
    rows.insert(rows.end(), r.rows.begin(), r.rows.end());
  return rows;
}

nlohmann::json run_summary(const WorldSpec& spec, const RunResult& result,
                           const std::vector<std::string>& overrides) {
  nlohmann::json replicates = nlohmann::json::array();
  std::vector<double> noa, largest, encounters_per_time;
  for (const ReplicateOutcome& r : result.replicates) {
    replicates.push_back(replicate_summary(r, spec.engine.dt));
    noa.push_back(r.final_row.noa);
    largest.push_back(r.final_row.largest);
    encounters_per_time.push_back(static_cast<double>(r.final_row.events.encounters) /
                                  r.final_row.time);
  }
  nlohmann::json pooled = nlohmann::json::object();
  add_aggregate_entries(pooled, pooled_leave(result), pooled_final_aggregates(result),
                        spec.engine.dt);
  return {{"swarmagg", SWARMAGG_VERSION},
          {"git", SWARMAGG_GIT_HASH},
          {"world", spec.name},
          {"overrides", overrides},
          {"engine", spec.engine.type == EngineType::Box2D ? "box2d" : "kinematic"},
          {"agents", spec.robots.count},
          {"steps", spec.steps()},
          {"duration", spec.run.duration},
          {"dt", spec.engine.dt},
          {"seed", spec.run.seed},
          {"threads", result.threads},
          {"step_threads", result.step_threads},
          {"wall_seconds", result.wall_seconds},
          {"final_noa", spread(noa)},
          {"final_largest", spread(largest)},
          {"encounters_per_time", spread(encounters_per_time)},
          {"pooled", pooled},
          {"replicates", replicates}};
}

std::string partitions_csv(const RunResult& result, std::int64_t steps) {
  std::string text = "replicate,partition,time_fraction\n";
  for (const ReplicateOutcome& r : result.replicates) {
    for (const auto& [partition, count] : r.partition_steps) {
      text += std::to_string(r.index) + "," + partition + "," +
              format_number(static_cast<double>(count) / static_cast<double>(steps)) + "\n";
    }
  }
  return text;
}

void write_run_folder(const WorldSpec& spec, const RunResult& result,
                      const std::filesystem::path& out, const std::vector<std::string>& overrides,
                      TimeseriesSpool* timeseries) {
  std::filesystem::create_directories(out);
  if (timeseries) {
    timeseries->commit();
  } else {
    write_timeseries_csv(out / "timeseries.csv", result);
  }
  if (records_partitions(spec)) {
    write_file_atomic(out / "partitions.csv", partitions_csv(result, spec.steps()));
  }
  write_file_atomic(out / "summary.json", run_summary(spec, result, overrides).dump(2) + "\n");
  // Written last: a folder whose resolved world matches is a complete run (reproduce reuses it).
  write_file_atomic(out / "world.resolved.yaml", resolved_world_text(spec));
}

bool holds_complete_run(const std::filesystem::path& folder) {
  std::error_code error;
  return std::filesystem::is_regular_file(folder / "world.resolved.yaml", error) &&
         std::filesystem::is_regular_file(folder / "summary.json", error) &&
         std::filesystem::is_regular_file(folder / "timeseries.csv", error);
}

std::string resolved_world_in(const std::filesystem::path& folder) {
  std::ifstream in(folder / "world.resolved.yaml", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError((folder / "world.resolved.yaml").string() + ": cannot be read");
  return text.str();
}

std::filesystem::path default_run_folder(const WorldSpec& spec) {
  return std::filesystem::path("runs") / spec.name;
}

}  // namespace swarmagg
