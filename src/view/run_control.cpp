#include "view/run_control.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "view/view_command.hpp"

namespace swarmagg {

RunControl::RunControl(std::int64_t duration_steps, double dt)
    : duration_steps_(duration_steps), dt_(dt) {}

void RunControl::play() {
  playing_ = true;
  owed_ = 0.0;
}

void RunControl::set_steps_per_frame(std::int64_t steps) {
  pace_ = Pace::StepsPerFrame;
  steps_per_frame_ = std::clamp<std::int64_t>(steps, 1, kMaxStepsPerFrame);
}

void RunControl::set_real_time(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw InputError("real-time factor " + std::to_string(factor) + ": expected > 0");
  pace_ = Pace::RealTime;
  real_time_factor_ = factor;
  owed_ = 0.0;
}

std::int64_t RunControl::steps_for_frame(std::int64_t steps_done, double frame_seconds) {
  std::int64_t playing_steps = 0;
  if (playing_ && steps_done < duration_steps_) {
    switch (pace_) {
      case Pace::StepsPerFrame:
        playing_steps = steps_per_frame_;
        break;
      case Pace::RealTime: {
        owed_ += real_time_factor_ * std::max(0.0, frame_seconds) / dt_;
        playing_steps = std::min<std::int64_t>(static_cast<std::int64_t>(owed_), kMaxStepsPerFrame);
        owed_ -= static_cast<double>(playing_steps);
        owed_ = std::min(owed_, 1.0);  // a slow frame is not made up for later
        break;
      }
      case Pace::Fastest:
        playing_steps = kMaxStepsPerFrame;
        break;
    }
    playing_steps = std::min(playing_steps, duration_steps_ - steps_done);
  }
  const std::int64_t total = playing_steps + requested_;
  requested_ = 0;
  return total;
}

bool RunControl::took(std::int64_t steps_done) {
  if (playing_ && !end_reported_ && steps_done >= duration_steps_) {
    playing_ = false;
    end_reported_ = true;
    return true;
  }
  return false;
}

void RunControl::restart() {
  playing_ = false;
  requested_ = 0;
  owed_ = 0.0;
  end_reported_ = false;
}

}  // namespace swarmagg
