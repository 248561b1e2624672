#pragma once
// The progress line on stderr of a run or a sweep: units done (replicates, runs), the
// percentage of the work and an ETA. Work is counted in agent-steps (robots.count x steps),
// reported while units are going, so the ETA is smooth and fair to units of different sizes.
// Thread-safe: each unit's ProgressObserver reports, the waiting thread prints.
// On a terminal the line is rewritten in place; elsewhere (a batch or Slurm log) a plain line
// is written every 10 % of the work or every 30 s, whichever comes first, and once at the end.
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "run/replicate_observer.hpp"

namespace swarmagg {

class ProgressLine {
 public:
  // `unit` names what is counted in the line, e.g. "runs".
  ProgressLine(std::string name, std::string unit, int total_units, double total_work);

  void add_work(double work);
  void finished_unit();
  // Called about every 250 ms while the units run: the live line, or a log line when due.
  void report();
  // Once the units are done: clears the live line, or writes the last log line.
  void finish();

 private:
  std::string name_;
  std::string unit_;
  int total_units_;
  double total_work_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_;
  mutable std::mutex mutex_;
  int done_units_ = 0;
  double done_work_ = 0.0;
  int logged_tenths_ = 0;   // tenths of the work done at the last log line
  int logged_units_ = -1;   // units done at the last log line
  double logged_at_ = 0.0;  // seconds since start_ at the last log line

  std::string text() const;  // with the mutex held
  double elapsed() const;
};

// Observes one replicate and reports its agent-steps to a progress line in batches.
class ProgressObserver : public ReplicateObserver {
 public:
  ProgressObserver(ProgressLine& progress, int agents, std::int64_t steps);

  void observe(const Replicate& replicate) override;
  void finish() override;  // reports what is left of the replicate's work

 private:
  static constexpr std::int64_t kBatch = 1024;  // steps between reports
  ProgressLine& progress_;
  double agents_;
  std::int64_t steps_;
  std::int64_t observed_ = -1;  // the first observation is the setup, not a step
  std::int64_t reported_ = 0;
};

}  // namespace swarmagg
