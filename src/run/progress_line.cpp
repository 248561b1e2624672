#include "run/progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace swarmagg {

namespace {

constexpr double kLogEverySeconds = 30.0;

}  // namespace

ProgressLine::ProgressLine(std::string name, std::string unit, int total_units, double total_work)
    : name_(std::move(name)),
      unit_(std::move(unit)),
      total_units_(total_units),
      total_work_(total_work),
      start_(std::chrono::steady_clock::now()),
      terminal_(::isatty(::fileno(stderr)) != 0) {}

void ProgressLine::add_work(double work) {
  std::lock_guard lock(mutex_);
  done_work_ += work;
}

void ProgressLine::finished_unit() {
  std::lock_guard lock(mutex_);
  ++done_units_;
}

double ProgressLine::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string ProgressLine::text() const {
  const double fraction = total_work_ > 0.0 ? std::min(1.0, done_work_ / total_work_) : 0.0;
  const double seconds = elapsed();
  char eta[32] = "eta --";
  if (fraction > 0.0) {
    std::snprintf(eta, sizeof eta, "eta %.0fs", seconds * (1.0 - fraction) / fraction);
  }
  char line[256];
  std::snprintf(line, sizeof line, "%s: %d/%d %s  %5.1f%% done  elapsed %.0fs  %s", name_.c_str(),
                done_units_, total_units_, unit_.c_str(), 100.0 * fraction, seconds, eta);
  return line;
}

void ProgressLine::report() {
  std::lock_guard lock(mutex_);
  if (terminal_) {
    std::fprintf(stderr, "\r%s   ", text().c_str());
    std::fflush(stderr);
    return;
  }
  const int tenths =
      total_work_ > 0.0 ? static_cast<int>(std::floor(10.0 * done_work_ / total_work_)) : 0;
  const double now = elapsed();
  if (tenths <= logged_tenths_ && now - logged_at_ < kLogEverySeconds) return;
  logged_tenths_ = tenths;
  logged_units_ = done_units_;
  logged_at_ = now;
  std::fprintf(stderr, "%s\n", text().c_str());
  std::fflush(stderr);
}

void ProgressLine::finish() {
  std::lock_guard lock(mutex_);
  if (terminal_) {
    std::fprintf(stderr, "\r%*s\r", 78, "");
  } else if (logged_tenths_ < 10 || logged_units_ != done_units_) {
    // A unit's work is all counted before its last writes, so a line logged in between says
    // 100 % with units still open: the log ends with the line that counts them all.
    std::fprintf(stderr, "%s\n", text().c_str());
  }
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
