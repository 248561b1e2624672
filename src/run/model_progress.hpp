#pragma once
// The progress of a model computation (`swarmagg model`, the model phase of `run`): the
// variants' walks report their model steps (models/output_grid.hpp). Every report first
// checks for Ctrl-C (run/interrupt.hpp), so a long prediction stops within a fraction of a
// second. The line (run/progress_line.hpp, counting variants) appears only once the
// computation has taken a second: most predictions take less and print nothing.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "run/progress_line.hpp"

namespace swarmagg {

class ModelProgress {
 public:
  static constexpr std::chrono::milliseconds kQuietFor{1000};

  // Not `shown`: Ctrl-C is still checked, nothing is printed. The line appears once
  // `quiet_for` has passed.
  ModelProgress(std::string name, int variants, double total_work, bool shown,
                std::chrono::milliseconds quiet_for = kQuietFor);

  // Throws Interrupted when a signal came.
  void add_work(std::int64_t steps);
  void finished_variant();
  // Once the outputs are written: clears the live line, or writes the last log line, when the
  // line was shown.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kReportEvery{250};

  std::optional<ProgressLine> line_;  // when shown
  Clock::time_point next_report_;
  bool reported_ = false;
};

}  // namespace swarmagg
