#include "sweep/sweep_runner.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/made_folders.hpp"
#include "plot/run_plots.hpp"
#include "run/interrupt.hpp"
#include "run/parallel_for.hpp"
#include "run/progress_line.hpp"
#include "run/run_folder.hpp"
#include "run/timeseries_spool.hpp"
#include "run/trajectory_output.hpp"
#include "run/world_runner.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_status.hpp"

namespace swarmagg {
namespace {

double run_work(const SweepRun& run) {
  return static_cast<double>(run.world.steps()) * run.world.robots.count;
}

// The rows go to a temporary beside timeseries.csv while the replicate runs (a long run
// holds none in memory), the other outputs are written once it has finished; an interrupted
// run removes its temporaries and the folder made for them, so it leaves no folder at all. An
// older unfinished attempt is cleared first.
void run_into_folder(const SweepRun& run, const std::filesystem::path& folder, bool plots,
                     ProgressLine& progress) {
  std::filesystem::remove_all(folder);
  const MadeFolders made(folder);
  const RemovedOnFailure unmade(made);
  TimeseriesSpool timeseries(folder / "timeseries.csv", 1);
  const auto trajectories = trajectory_writer(run.world, folder);
  const ObserverFactory progress_observer = [&](int) -> std::unique_ptr<ReplicateObserver> {
    return std::make_unique<ProgressObserver>(progress, run.world.robots.count, run.world.steps());
  };
  auto observer = both_observers(
      progress_observer, trajectory_observers(trajectories.get(), run.world.run.trajectories))(0);
  RunResult result;
  result.replicates.push_back(
      run_replicate(run.world, 0, observer.get(), {.timeseries = &timeseries}));
  result.wall_seconds = result.replicates.front().wall_seconds;
  observer.reset();  // releases the trajectory's datasets before the file closes
  if (trajectories) trajectories->commit();
  write_run_folder(run.world, result, folder, point_overrides(run.point), &timeseries);
  if (!plots) return;
  // A plot gnuplot cannot draw leaves the run complete; `swarmagg plot` can redraw it.
  for (const std::string& failure : draw_run_plots(folder, folder).failures) {
    std::cerr << "warning: " + folder.string() + ": " + failure + "\n";
  }
}

// Replicates of one point running side by side share its folder, which only the first to
// make it would remove when they are stopped, and only once empty, which it may not be yet:
// the point folders left empty (and runs/, if all are) are removed once every run has stopped.
void remove_empty_point_folders(const std::vector<SweepRun>& runs,
                                const std::filesystem::path& out) {
  for (const SweepRun& run : runs) {
    std::error_code not_empty;
    std::filesystem::remove(sweep_run_folder(out, run).parent_path(), not_empty);
  }
  std::error_code not_empty;
  std::filesystem::remove(out / "runs", not_empty);
}

int thread_count(int requested, std::size_t runs) {
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(requested > 0 ? requested : machine, 1,
                    static_cast<int>(std::max<std::size_t>(runs, 1)));
}

void run_parallel(const std::vector<SweepRun>& runs, const SweepOptions& options,
                  ProgressLine& progress, int threads) {
  if (runs.empty()) return;  // a resumed sweep with every run complete: no "0/0 runs" line
  auto run_one = [&](std::size_t i) {
    throw_if_interrupted();
    run_into_folder(runs[i], sweep_run_folder(options.out, runs[i]), options.plots, progress);
    progress.finished_unit();
  };
  try {
    parallel_for(runs.size(), threads, run_one,
                 options.progress ? std::function<void()>([&] { progress.report(); }) : nullptr);
  } catch (...) {
    remove_empty_point_folders(runs, options.out);
    throw;
  }
  if (options.progress) progress.finish();
}

// Shards sharing one output folder all write the same manifest; leaving an identical one
// alone keeps them from racing on it.
void write_manifest(const std::filesystem::path& out, const SweepPlan& plan) {
  const std::string text = manifest_text(plan);
  std::ifstream in(out / kManifestFile, std::ios::binary);
  std::ostringstream existing;
  existing << in.rdbuf();
  if (!in || existing.str() != text) write_file_atomic(out / kManifestFile, text);
}

// A folder a sweep may write into: missing, empty but for hidden temporaries (shards of a job
// array start at once, one of them writing the manifest), or this sweep's own (a manifest of
// the same name: values, replicates or seed may have changed since, see the outdated runs).
void check_is_this_sweeps_folder(const std::filesystem::path& out, const SweepPlan& plan,
                                 bool replace) {
  if (std::filesystem::exists(out / kManifestFile)) {
    const SweepPlan earlier = read_manifest(out);
    if (earlier.name == plan.name || replace) return;
    throw InputError(out.string() + "/ holds the sweep '" + earlier.name + "', not '" + plan.name +
                     "'; pass --force to write this one there anyway, or --out DIR (force=True or "
                     "out= in Python)");
  }
  std::error_code missing;
  for (const auto& entry : std::filesystem::directory_iterator(out, missing)) {
    if (entry.path().filename().string().starts_with(".")) continue;
    throw InputError(
        out.string() + "/ holds files but no " + kManifestFile +
        ": not a sweep's folder (an earlier run?); use --out DIR (out= in Python) for the sweep");
  }
}

// Runs whose folders hold a complete run of another world are results someone may still
// need: they are replaced only when asked.
void check_no_outdated_runs(const std::filesystem::path& out, const std::vector<SweepRun>& runs) {
  std::size_t outdated = 0;
  const SweepRun* example = nullptr;
  for (const SweepRun& run : runs) {
    if (sweep_run_status(out, run) != RunStatus::Outdated) continue;
    ++outdated;
    if (example == nullptr) example = &run;
  }
  if (outdated == 0) return;
  throw InputError(
      out.string() + "/: " + std::to_string(outdated) +
      (outdated == 1 ? " run holds" : " runs hold") +
      " results of another world (the base world, seed or values changed since they ran), "
      "e.g. " +
      sweep_run_folder(out, *example).string() +
      "; pass --force (force=True in Python) to replace them, or --out DIR to keep them");
}

}  // namespace

std::vector<SweepRun> shard_runs(std::vector<SweepRun> runs, Shard shard) {
  std::erase_if(runs, [shard](const SweepRun& run) { return !shard.contains(run.index); });
  return runs;
}

SweepReport run_sweep(const SweepPlan& plan, const SweepOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<SweepRun> pending = shard_runs(expand_sweep(plan), options.shard);
  SweepReport report;
  report.selected = static_cast<int>(pending.size());
  check_is_this_sweeps_folder(options.out, plan, options.replace_outdated);
  if (!options.replace_outdated) check_no_outdated_runs(options.out, pending);
  std::erase_if(pending, [&](const SweepRun& run) {
    return sweep_run_status(options.out, run) == RunStatus::Complete;
  });
  report.already_complete = report.selected - static_cast<int>(pending.size());
  write_manifest(options.out, plan);
  double work = 0.0;
  for (const SweepRun& run : pending) work += run_work(run);
  ProgressLine progress(plan.name, "runs", static_cast<int>(pending.size()), work);
  report.threads = thread_count(options.threads, pending.size());
  run_parallel(pending, options, progress, report.threads);
  report.ran = static_cast<int>(pending.size());
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace swarmagg
