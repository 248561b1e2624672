#pragma once
// The sweep's progress line on stderr: runs done, percentage of the work and an ETA. Work
// is counted in agent-steps (robots.count x steps), reported while runs are going, so the
// ETA is smooth and fair to sweeps over durations or swarm sizes. Thread-safe: workers
// report, the main thread prints.
#include <chrono>
#include <mutex>
#include <string>

#include "run/replicate_observer.hpp"

namespace swarmagg {

class SweepProgress {
 public:
  SweepProgress(std::string name, int total_runs, double total_work);

  void add_work(double work);
  void finished_run();
  void print() const;
  void clear() const;

 private:
  std::string name_;
  int total_runs_;
  double total_work_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  int done_runs_ = 0;
  double done_work_ = 0.0;
};

// Observes one run and reports its agent-steps to the sweep's progress in batches.
class RunProgress : public ReplicateObserver {
 public:
  RunProgress(SweepProgress& progress, int agents, std::int64_t steps);

  void observe(const Replicate& replicate) override;
  void finish() override;  // reports what is left of the run's work

 private:
  static constexpr std::int64_t kBatch = 1024;  // steps between reports
  SweepProgress& progress_;
  double agents_;
  std::int64_t steps_;
  std::int64_t observed_ = -1;  // the first observation is the setup, not a step
  std::int64_t reported_ = 0;
};

}  // namespace swarmagg
