#pragma once
// The progress line on stderr of a run or a sweep: units done (replicates, runs), the
// percentage of the work and an ETA. Work is counted in agent-steps (robots.count x steps),
// reported while units are going, so the ETA is smooth and fair to units of different sizes.
// Thread-safe: each unit's ProgressObserver reports, the waiting thread prints.
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
  void print() const;
  void clear() const;

 private:
  std::string name_;
  std::string unit_;
  int total_units_;
  double total_work_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  int done_units_ = 0;
  double done_work_ = 0.0;
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
