#include "sweep/sweep_runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>

#include "output/atomic_file.hpp"
#include "plot/run_plots.hpp"
#include "run/interrupt.hpp"
#include "run/run_folder.hpp"
#include "run/world_runner.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_progress.hpp"
#include "sweep/sweep_status.hpp"

namespace swarmagg {
namespace {

double run_work(const SweepRun& run) {
  return static_cast<double>(run.world.steps()) * run.world.robots.count;
}

// The outputs are written only once the replicate has finished, so an interrupted run
// leaves no folder at all; an older unfinished attempt is cleared first.
void run_into_folder(const SweepRun& run, const std::filesystem::path& folder, bool plots,
                     SweepProgress& progress) {
  std::filesystem::remove_all(folder);
  RunProgress observer(progress, run.world.robots.count, run.world.steps());
  RunResult result;
  result.replicates.push_back(run_replicate(run.world, 0, &observer));
  result.wall_seconds = result.replicates.front().wall_seconds;
  write_run_folder(run.world, result, folder);
  if (!plots) return;
  // A plot gnuplot cannot draw leaves the run complete; `swarmagg plot` can redraw it.
  for (const std::string& failure : draw_run_plots(folder, folder).failures) {
    std::cerr << "warning: " + folder.string() + ": " + failure + "\n";
  }
}

int thread_count(int requested, std::size_t runs) {
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::clamp(requested > 0 ? requested : machine, 1,
                    static_cast<int>(std::max<std::size_t>(runs, 1)));
}

class RunPool {
 public:
  RunPool(const std::vector<SweepRun>& runs, const std::filesystem::path& out, bool plots,
          SweepProgress& progress)
      : runs_(runs), out_(out), plots_(plots), progress_(progress) {}

  void work() {
    ++working_;
    for (std::size_t i = next_++; i < runs_.size(); i = next_++) {
      try {
        throw_if_interrupted();
        run_into_folder(runs_[i], sweep_run_folder(out_, runs_[i]), plots_, progress_);
        progress_.finished_run();
      } catch (...) {
        std::lock_guard lock(failure_mutex_);
        if (!failure_) failure_ = std::current_exception();
        next_ = runs_.size();  // hand out no more runs
      }
    }
    --working_;
  }

  bool done() const { return next_ >= runs_.size() && working_ == 0; }

  void rethrow_failure() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  const std::vector<SweepRun>& runs_;
  const std::filesystem::path& out_;
  bool plots_;
  SweepProgress& progress_;
  std::atomic<std::size_t> next_{0};
  std::atomic<int> working_{0};
  std::mutex failure_mutex_;
  std::exception_ptr failure_;
};

void run_parallel(const std::vector<SweepRun>& runs, const SweepOptions& options,
                  SweepProgress& progress, int threads) {
  RunPool pool(runs, options.out, options.plots, progress);
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back([&pool] { pool.work(); });
  const bool show = options.progress && ::isatty(::fileno(stderr));
  while (show && !pool.done()) {
    progress.print();
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  for (std::thread& worker : workers) worker.join();
  if (show) progress.clear();
  pool.rethrow_failure();
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
  std::erase_if(pending, [&](const SweepRun& run) {
    return sweep_run_status(options.out, run) == RunStatus::Complete;
  });
  report.already_complete = report.selected - static_cast<int>(pending.size());
  write_manifest(options.out, plan);
  double work = 0.0;
  for (const SweepRun& run : pending) work += run_work(run);
  SweepProgress progress(plan.name, static_cast<int>(pending.size()), work);
  report.threads = thread_count(options.threads, pending.size());
  run_parallel(pending, options, progress, report.threads);
  report.ran = static_cast<int>(pending.size());
  report.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace swarmagg
