#include "sweep/sweep_progress.hpp"

#include <cstdio>

namespace swarmagg {

SweepProgress::SweepProgress(std::string name, int total_runs, double total_work)
    : name_(std::move(name)),
      total_runs_(total_runs),
      total_work_(total_work),
      start_(std::chrono::steady_clock::now()) {}

void SweepProgress::add_work(double work) {
  std::lock_guard lock(mutex_);
  done_work_ += work;
}

void SweepProgress::finished_run() {
  std::lock_guard lock(mutex_);
  ++done_runs_;
}

void SweepProgress::print() const {
  std::lock_guard lock(mutex_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = total_work_ > 0.0 ? done_work_ / total_work_ : 0.0;
  char eta[32] = "eta --";
  if (fraction > 0.0) {
    std::snprintf(eta, sizeof eta, "eta %.0fs", elapsed * (1.0 - fraction) / fraction);
  }
  std::fprintf(stderr, "\r%s: %d/%d runs  %5.1f%%  elapsed %.0fs  %s   ", name_.c_str(), done_runs_,
               total_runs_, 100.0 * fraction, elapsed, eta);
  std::fflush(stderr);
}

void SweepProgress::clear() const {
  std::fprintf(stderr, "\r%*s\r", 78, "");
  std::fflush(stderr);
}

RunProgress::RunProgress(SweepProgress& progress, int agents, std::int64_t steps)
    : progress_(progress), agents_(agents), steps_(steps) {}

void RunProgress::observe(const Replicate&) {
  if (++observed_ - reported_ < kBatch) return;
  progress_.add_work(agents_ * static_cast<double>(observed_ - reported_));
  reported_ = observed_;
}

void RunProgress::finish() {
  progress_.add_work(agents_ * static_cast<double>(steps_ - reported_));
  reported_ = steps_;
}

}  // namespace swarmagg
