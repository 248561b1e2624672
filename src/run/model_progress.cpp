#include "run/model_progress.hpp"

#include "run/interrupt.hpp"

namespace swarmagg {

ModelProgress::ModelProgress(std::string name, int variants, double total_work, bool shown,
                             std::chrono::milliseconds quiet_for)
    : next_report_(Clock::now() + quiet_for) {
  if (shown) line_.emplace(std::move(name), "variants", variants, total_work);
}

void ModelProgress::add_work(std::int64_t steps) {
  throw_if_interrupted();
  if (!line_) return;
  line_->add_work(static_cast<double>(steps));
  const Clock::time_point now = Clock::now();
  if (now < next_report_) return;
  next_report_ = now + kReportEvery;
  line_->report();
  reported_ = true;
}

void ModelProgress::finished_variant() {
  if (line_) line_->finished_unit();
}

void ModelProgress::finish() {
  if (reported_) line_->finish();
}

}  // namespace swarmagg
