#pragma once
// When the live view steps its replicate: a small state machine, apart from the window so it
// can be tested alone. Playing, it takes a number of steps each frame, chosen by the pace:
// a fixed count per frame (1 .. kMaxStepsPerFrame), a real-time factor (simulated time per
// wall-clock second) or as many as fit in a frame's time budget. Playing stops at the
// world's duration, once; single steps asked for explicitly (`.`, right arrow, `step N`) are
// taken whether playing or not, also past the duration.
#include <cstdint>

namespace swarmagg {

enum class Pace { StepsPerFrame, RealTime, Fastest };

class RunControl {
 public:
  RunControl(std::int64_t duration_steps, double dt);

  void play();
  void pause() { playing_ = false; }
  void toggle() { playing_ ? pause() : play(); }
  bool playing() const { return playing_; }

  void set_steps_per_frame(std::int64_t steps);  // clamped to 1 .. kMaxStepsPerFrame
  void set_real_time(double factor);             // > 0
  void set_fastest() { pace_ = Pace::Fastest; }
  Pace pace() const { return pace_; }
  std::int64_t steps_per_frame() const { return steps_per_frame_; }
  double real_time_factor() const { return real_time_factor_; }

  void request_steps(std::int64_t steps) { requested_ += steps; }

  // The steps to take this frame, `steps_done` having been taken, the last frame having
  // lasted `frame_seconds`. Fastest gives kMaxStepsPerFrame: the caller stops early when
  // its time budget is spent and reports the steps it took with took().
  std::int64_t steps_for_frame(std::int64_t steps_done, double frame_seconds);
  // True once, after the step that reaches the duration while playing (then paused).
  bool took(std::int64_t steps_done);
  // Back to step 0 (reset or reseed): paused, nothing requested, the end not yet reached.
  void restart();

  std::int64_t duration_steps() const { return duration_steps_; }

 private:
  std::int64_t duration_steps_;
  double dt_;
  bool playing_ = false;
  Pace pace_ = Pace::StepsPerFrame;
  std::int64_t steps_per_frame_ = 1;
  double real_time_factor_ = 1.0;
  double owed_ = 0.0;  // fraction of a step carried over between frames (real time)
  std::int64_t requested_ = 0;
  bool end_reported_ = false;
};

}  // namespace swarmagg
