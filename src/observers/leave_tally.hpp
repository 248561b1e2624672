#pragma once
// What one replicate's LEAVE episodes add up to (docs/models.md): attempts and escapes split by
// where the leaver stood when it started (rim or inside, the rim rule of docs/models.md), and per
// aggregate size m the attempts, escapes and the exposure, the number of steps times the
// aggregates of size m that existed, so escapes / (exposure dt) is the escape rate per
// aggregate of size m, to set beside the models' m p / dt and periph(m) p / dt.
// Tallies of replicates add up (+=) to a pooled tally.
#include <cstdint>
#include <vector>

namespace swarmagg {

struct RimSplit {
  std::int64_t rim = 0;
  std::int64_t inside = 0;
  std::int64_t total() const { return rim + inside; }
  void count(bool on_rim) { (on_rim ? rim : inside) += 1; }
  RimSplit& operator+=(const RimSplit& other) {
    rim += other.rim;
    inside += other.inside;
    return *this;
  }
};

struct LeaveTally {
  // Attempts count when they start; escapes when they end. An attempt still under way when
  // the run ends is an attempt and not an escape.
  RimSplit attempts;
  RimSplit escapes;
  // Indexed by aggregate size m (the size of the aggregate the leaver left), 0 .. N.
  std::vector<std::int64_t> attempts_by_size;
  std::vector<std::int64_t> escapes_by_size;
  std::vector<std::int64_t> aggregate_steps_by_size;
  // Returns (observers/leave_episodes.hpp), by the size m left: the attempts whose return
  // window closed within the run (one still open when it ended could yet have returned: the
  // fraction that returned counts only the others), how many of them returned, and their
  // summed time away in steps; by the size of the aggregate joined on return (0: a lone member
  // that kept waiting); and by aggregate size k, the steps that size-k aggregates existed while
  // returning agents were away (searcher exposure that was no search). The last two count
  // every return, the run's last ones too: those joins were no new ones either.
  std::vector<std::int64_t> return_attempts_by_size;
  std::vector<std::int64_t> returns_by_size;
  std::vector<std::int64_t> return_steps_by_size, return_square_steps_by_size;
  std::vector<std::int64_t> returns_into_size;
  std::vector<std::int64_t> returning_aggregate_steps_by_size;

  // Room for every size an aggregate of `agent_count` agents can have.
  void resize(int agent_count);
  // The summed tu that aggregates of `size` existed (0 beyond the sizes counted).
  double aggregate_time(int size, double dt) const;
  int largest_size() const { return static_cast<int>(aggregate_steps_by_size.size()) - 1; }
  LeaveTally& operator+=(const LeaveTally& other);
};

}  // namespace swarmagg
