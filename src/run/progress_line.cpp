#include "run/progress_line.hpp"

#include <cstdio>

namespace swarmagg {

ProgressLine::ProgressLine(std::string name, std::string unit, int total_units, double total_work)
    : name_(std::move(name)),
      unit_(std::move(unit)),
      total_units_(total_units),
      total_work_(total_work),
      start_(std::chrono::steady_clock::now()) {}

void ProgressLine::add_work(double work) {
  std::lock_guard lock(mutex_);
  done_work_ += work;
}

void ProgressLine::finished_unit() {
  std::lock_guard lock(mutex_);
  ++done_units_;
}

void ProgressLine::print() const {
  std::lock_guard lock(mutex_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = total_work_ > 0.0 ? done_work_ / total_work_ : 0.0;
  char eta[32] = "eta --";
  if (fraction > 0.0) {
    std::snprintf(eta, sizeof eta, "eta %.0fs", elapsed * (1.0 - fraction) / fraction);
  }
  std::fprintf(stderr, "\r%s: %d/%d %s  %5.1f%%  elapsed %.0fs  %s   ", name_.c_str(), done_units_,
               total_units_, unit_.c_str(), 100.0 * fraction, elapsed, eta);
  std::fflush(stderr);
}

void ProgressLine::clear() const {
  std::fprintf(stderr, "\r%*s\r", 78, "");
  std::fflush(stderr);
}

ProgressObserver::ProgressObserver(ProgressLine& progress, int agents, std::int64_t steps)
    : progress_(progress), agents_(agents), steps_(steps) {}

void ProgressObserver::observe(const Replicate&) {
  if (++observed_ - reported_ < kBatch) return;
  progress_.add_work(agents_ * static_cast<double>(observed_ - reported_));
  reported_ = observed_;
}

void ProgressObserver::finish() {
  progress_.add_work(agents_ * static_cast<double>(steps_ - reported_));
  reported_ = steps_;
}

}  // namespace swarmagg
