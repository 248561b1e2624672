#pragma once
// Agents sorted into horizontal strips at least `window` high, and by x within each strip,
// kept as structure-of-arrays in that order. A pair closer than `window` then lies in one
// strip or two adjacent ones, within an x-window of 2 * window: the scan compares each
// agent with a handful of others, reading memory sequentially, with no empty cells to sweep.
//
// Each strip ends with a sentinel slot at x = +infinity, so the inner loops need no bound
// check. Agents move little per step, so `update` starts from the previous order, in two
// passes over the slots: the first refreshes positions in place and lifts out the few agents
// that changed strip; the second copies every strip to the other buffer, merging in its
// arrivals (sorted by x) and moving back the rare agent that overtook another in x. Keeping
// the order costs O(N) and allocates nothing after warm-up.
#include <algorithm>
#include <cstdint>
#ifdef __SSE2__
#include <emmintrin.h>
#endif
#include <limits>
#include <span>
#include <vector>

#include "core/agent_array.hpp"
#include "core/vec2.hpp"
#include "engine/kinematic/step_threads.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

class SortedStrips {
 public:
  static constexpr std::uint32_t kNoAgent = std::numeric_limits<std::uint32_t>::max();
  // Slots after the last strip, read by look-ahead (as sentinels: x = infinity, no agent).
  // Also how far ahead refresh_strips prefetches: in a million agents nearly every read by
  // id misses to memory, and 64 agents' work covers that latency where 16 did not (one
  // update of the bench world at 10^6 agents: 8.2 -> 5.9 ms).
  static constexpr std::uint32_t kLookAhead = 64;

  // Whether the arena is large enough for strips of `window`: at least three strips, and
  // three windows across, so that no pair is met twice around the torus.
  static bool fits(const ArenaGeometry& arena, double window);

  // Sorts the agents at `positions` (by id) into strips at least `window` high, starting
  // from the previous order when nothing but the positions changed.
  void update(const ArenaGeometry& arena, double window, std::span<const Vec2> positions,
              StepThreads& threads);

  // Calls visit(a, b) for every pair of slots whose agents lie within `window` of each
  // other (torus-aware), once: strips [first, last) scan themselves and the strip above.
  template <typename Visit>
  void for_each_candidate(int first, int last, Visit&& visit) const;

  int strips() const { return strips_; }
  std::uint32_t id(std::uint32_t slot) const { return id_[slot]; }
  Vec2 position(std::uint32_t slot) const { return {x_[slot], y_[slot]}; }

 private:
  struct Layout {
    int strips = 1;
    double strip_scale = 1.0;  // strips per unit length (y)
    std::uint32_t strip_of(double y) const;
    bool operator==(const Layout&) const = default;
  };
  static Layout layout_for(const ArenaGeometry& arena, double window);

  // An agent that changed strip since the last update: where it is now, which strip it
  // entered and which slot it left.
  struct Arrival {
    double x = 0.0;
    double y = 0.0;
    std::uint32_t id = 0;
    std::uint32_t strip = 0;
    std::uint32_t slot = 0;
  };

  // Slots of strip s: [strip_first(s), strip_sentinel(s)).
  std::uint32_t strip_first(int s) const { return strip_begin_[static_cast<std::size_t>(s)]; }
  std::uint32_t strip_sentinel(int s) const { return strip_first(s + 1) - 1; }

  bool same_layout(const ArenaGeometry& arena, double window, std::size_t agents) const;
  void sort_from_scratch(std::span<const Vec2> positions);
  int first_strip(int task, int tasks) const {
    return static_cast<int>(
        StepThreads::slice_begin(static_cast<std::size_t>(strips_), task, tasks));
  }
  void restrip(std::span<const Vec2> positions, StepThreads& threads);
  void refresh_strips(std::span<const Vec2> positions, int task, int first, int last);
  void sort_arrivals(int tasks);
  void merge_strips(int task, int first, int last);

  template <typename Visit>
  void scan_strip(int s, Visit& visit) const;
  static std::uint32_t advance_past(const double* x, std::uint32_t low, double from);
  template <typename Visit>
  void scan_seam(int s, std::uint32_t a, Visit& visit) const;

  ArenaGeometry arena_{1.0, 1.0, Topology::Torus};
  double window_ = 0.0;
  Layout layout_;
  int strips_ = 0;
  std::size_t agents_ = 0;
  // Slots of strip s start at strip_begin_[s]; its sentinel ends it. strips + 1 entries.
  std::vector<std::uint32_t> strip_begin_;
  AgentArray<double> x_;
  AgentArray<double> y_;
  AgentArray<std::uint32_t> id_;
  // The restrip's scratch: the other buffer (swapped in when done) and its strip bounds;
  // the agents that changed strip, per task of the first pass, then by destination strip
  // (arrival_begin_[s] is the first of strip s).
  std::vector<std::uint32_t> next_begin_;
  AgentArray<double> next_x_;
  AgentArray<double> next_y_;
  AgentArray<std::uint32_t> next_id_;
  std::vector<std::vector<Arrival>> leavers_;  // in slot order
  std::vector<std::uint32_t> departures_;      // per strip
  std::vector<Arrival> arrivals_;
  std::vector<std::uint32_t> arrival_begin_;
};

// Positions are never negative (walls keep bodies inside, the torus wraps); the unsigned
// minimum only keeps a stray value inside the table.
inline std::uint32_t SortedStrips::Layout::strip_of(double y) const {
  return std::min(static_cast<unsigned>(static_cast<int>(y * strip_scale)),
                  static_cast<unsigned>(strips - 1));
}

template <typename Visit>
void SortedStrips::for_each_candidate(int first, int last, Visit&& visit) const {
  for (int s = first; s < last; ++s) scan_strip(s, visit);
}

// The first slot from `low` on whose x is not below `from`, the strip being sorted up to its
// sentinel. The strip above holds about as many agents as this one, so the answer moves about
// one slot per agent, and scan_strip starts each agent from the answer two agents back: eight
// slots are compared at once, without branches (a mispredicted loop exit per agent would cost
// more), and the loads do not wait on each other, as they would when stepping one slot at a
// time: `low` carries from agent to agent, so its update is the scan's critical path. The
// slots compared may lie past the sentinel (in the next strip or the padding), hence only the
// leading run of slots below `from` counts.
inline std::uint32_t SortedStrips::advance_past(const double* x, std::uint32_t low, double from) {
#ifdef __SSE2__
  const __m128d bound = _mm_set1_pd(from);
  const int below = _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(x + low), bound)) |
                    _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(x + low + 2), bound)) << 2 |
                    _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(x + low + 4), bound)) << 4 |
                    _mm_movemask_pd(_mm_cmplt_pd(_mm_loadu_pd(x + low + 6), bound)) << 6;
  low += static_cast<std::uint32_t>(__builtin_ctz(~below));  // the leading run's length
#else
  const unsigned first = x[low] < from;
  const unsigned second = first & (x[low + 1] < from);
  const unsigned third = second & (x[low + 2] < from);
  const unsigned fourth = third & (x[low + 3] < from);
  low += first + second + third + fourth;
#endif
  while (x[low] < from) ++low;
  return low;
}

template <typename Visit>
void SortedStrips::scan_strip(int s, Visit& visit) const {
  const std::uint32_t begin = strip_first(s), end = strip_sentinel(s);
  if (begin == end) return;
  const bool top = s + 1 == strips_;
  const bool above = arena_.torus() || !top;
  const double window = window_, window2 = window * window;
  const double shift_y = top ? arena_.height() : 0.0;
  const double* x = x_.data();
  const double* y = y_.data();
  // On a torus, agents within a window of either edge also look across the seam: slots
  // [begin, inner) and [outer, end).
  std::uint32_t inner = begin, outer = end;
  if (arena_.torus()) {
    while (inner < end && x[inner] - window < 0.0) ++inner;
    while (outer > inner && x[outer - 1] + window >= arena_.width()) --outer;
  }
  // The first slot of the strip above within the window of the agent before (`low`) and of
  // the one before that (`earlier`). Each agent's search starts from the latter: any slot up
  // to its own answer gives the same answer (the strip above is sorted by x, and xa - window
  // grows from agent to agent), and the search then waits only on the agent two back, so
  // that two agents' searches overlap (scan at 10^4 agents: 0.113 -> 0.105 ms; from the
  // agent just before, or four slots at once, it was no faster).
  std::uint32_t low = above ? strip_first(top ? 0 : s + 1) : end, earlier = low;
  for (std::uint32_t a = begin; a < end; ++a) {
    const double xa = x[a], ya = y[a];
    const double high = xa + window;
    // The same strip, ahead in x (the sentinel ends the loop).
    for (std::uint32_t b = a + 1; x[b] <= high; ++b) {
      const double dx = x[b] - xa, dy = y[b] - ya;
      if (dx * dx + dy * dy <= window2) visit(a, b);
    }
    // The strip above, within [xa - window, xa + window]; `low` only moves forward. (Without
    // a strip above, `low` rests on this strip's sentinel and the loop does nothing.)
    const double ya_below = ya - shift_y, from = xa - window;
    const std::uint32_t latest = advance_past(x, earlier, from);
    earlier = low;
    low = latest;
    for (std::uint32_t b = low; x[b] <= high; ++b) {
      const double dx = x[b] - xa, dy = y[b] - ya_below;
      if (dx * dx + dy * dy <= window2) visit(a, b);
    }
    if (a < inner || a >= outer) scan_seam(s, a, visit);
  }
}

// Pairs across the x seam of a torus for slot a of strip s: partners near the other edge
// of the same strip (met from the agent near x = width only) and of the strip above.
template <typename Visit>
void SortedStrips::scan_seam(int s, std::uint32_t a, Visit& visit) const {
  const bool top = s + 1 == strips_;
  const int t = top ? 0 : s + 1;
  const double width = arena_.width(), shift_y = top ? arena_.height() : 0.0;
  const double window = window_, window2 = window * window;
  const double xa = x_[a], ya = y_[a];
  auto test = [&](std::uint32_t b, double shift_x, double dy_shift) {
    const double dx = x_[b] + shift_x - xa, dy = y_[b] + dy_shift - ya;
    if (dx * dx + dy * dy <= window2) visit(a, b);
  };
  const std::uint32_t first = strip_first(s), t_first = strip_first(t), t_end = strip_sentinel(t);
  if (xa + window >= width) {
    for (std::uint32_t b = first; x_[b] + width <= xa + window; ++b) test(b, width, 0.0);
    for (std::uint32_t b = t_first; x_[b] + width <= xa + window; ++b) test(b, width, shift_y);
  }
  if (xa - window < 0.0) {
    for (std::uint32_t b = t_end; b > t_first && x_[b - 1] - width >= xa - window; --b) {
      test(b - 1, -width, shift_y);
    }
  }
}

}  // namespace swarmagg
