#include "engine/kinematic/sorted_strips.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Room for this share of the agents (plus a few) changing strip in one update, reserved up
// front: updates several steps apart (Verlet lists) see more changes than single steps, and
// the buffers would otherwise reach new heights now and then long into a run.
constexpr std::size_t kStripChangesRoom = 16;
constexpr std::size_t kStripChangesFloor = 64;

int tasks_for(std::size_t agents, int strips, const StepThreads& threads) {
  const auto by_work = static_cast<int>(agents / StepThreads::kAgentsPerTask);
  return std::max(1, std::min({threads.size(), by_work, strips}));
}

// Writes an agent at slot `end` of a strip starting at `begin` whose last agent lies
// further in x, moving it back to its place (rare: agents overtake each other in x only now
// and then). Arguments by value, so that the caller's cursors can stay in registers.
[[gnu::noinline]] void insert_back(double* x, double* y, std::uint32_t* id, std::uint32_t begin,
                                   std::uint32_t end, double px, double py, std::uint32_t pid) {
  std::uint32_t j = end;
  do {
    x[j] = x[j - 1];
    y[j] = y[j - 1];
    id[j] = id[j - 1];
    --j;
  } while (j > begin && px < x[j - 1]);
  x[j] = px;
  y[j] = py;
  id[j] = pid;
}

}  // namespace

bool SortedStrips::fits(const ArenaGeometry& arena, double window) {
  return std::floor(arena.height() / window) >= 3.0 && arena.width() >= 3.0 * window;
}

SortedStrips::Layout SortedStrips::layout_for(const ArenaGeometry& arena, double window) {
  Layout layout;
  layout.strips = static_cast<int>(std::floor(arena.height() / window));
  layout.strip_scale = layout.strips / arena.height();
  return layout;
}

bool SortedStrips::same_layout(const ArenaGeometry& arena, double window,
                               std::size_t agents) const {
  return strips_ > 0 && window == window_ && agents == agents_ && arena.width() == arena_.width() &&
         arena.height() == arena_.height() && arena.torus() == arena_.torus() &&
         layout_for(arena, window) == layout_;
}

void SortedStrips::update(const ArenaGeometry& arena, double window,
                          std::span<const Vec2> positions, StepThreads& threads) {
  if (same_layout(arena, window, positions.size())) return restrip(positions, threads);
  arena_ = arena;
  window_ = window;
  layout_ = layout_for(arena, window);
  strips_ = layout_.strips;
  agents_ = positions.size();
  sort_from_scratch(positions);
}

// A counting sort by strip, then a sort by (x, id) within each strip.
void SortedStrips::sort_from_scratch(std::span<const Vec2> positions) {
  const std::size_t n = positions.size();
  const auto strips = static_cast<std::size_t>(strips_);
  const std::size_t padded = n + strips + kLookAhead;
  // Counts land one strip ahead, so that the running sum leaves each strip's first slot.
  strip_begin_.assign(strips + 1, 0);
  for (const Vec2& p : positions) ++strip_begin_[layout_.strip_of(p.y) + 1];
  std::uint32_t base = 0;
  for (std::size_t s = 1; s <= strips; ++s) {
    base += strip_begin_[s] + 1;  // the strip's agents and its sentinel
    strip_begin_[s] = base;
  }
  // The padding after the last strip reads as sentinels, in both buffers.
  x_.assign(padded, kInfinity);
  y_.assign(padded, 0.0);
  id_.assign(padded, kNoAgent);
  next_x_ = x_;
  next_y_ = y_;
  next_id_ = id_;
  next_begin_ = strip_begin_;
  std::vector<std::uint32_t> cursor(strip_begin_.begin(), strip_begin_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    id_[cursor[layout_.strip_of(positions[i].y)]++] = static_cast<std::uint32_t>(i);
  }
  for (int s = 0; s < strips_; ++s) {
    auto first = id_.begin() + strip_first(s), last = id_.begin() + strip_sentinel(s);
    std::sort(first, last, [&](std::uint32_t a, std::uint32_t b) {
      return positions[a].x < positions[b].x || (positions[a].x == positions[b].x && a < b);
    });
    for (auto it = first; it != last; ++it) {
      x_[it - id_.begin()] = positions[*it].x;
      y_[it - id_.begin()] = positions[*it].y;
    }
  }
  departures_.assign(strips, 0);
  arrival_begin_.assign(strips + 1, 0);
}

// Both passes split the strips the same way among tasks, so that each task of the second
// finds in its own list (in slot order) the slots its strips lost. Agents that changed strip
// are gathered between the passes, in task order: the result is exactly the sequential one.
void SortedStrips::restrip(std::span<const Vec2> positions, StepThreads& threads) {
  const int tasks = tasks_for(agents_, strips_, threads);
  if (leavers_.size() < static_cast<std::size_t>(tasks)) {
    leavers_.resize(static_cast<std::size_t>(tasks));
    const std::size_t room = agents_ / kStripChangesRoom + kStripChangesFloor;
    for (std::vector<Arrival>& leavers : leavers_) leavers.reserve(room);
    arrivals_.reserve(room);
  }
  auto refresh = [&](int task) {
    refresh_strips(positions, task, first_strip(task, tasks), first_strip(task + 1, tasks));
  };
  threads.run(tasks, refresh);
  sort_arrivals(tasks);
  auto merge = [&](int task) {
    merge_strips(task, first_strip(task, tasks), first_strip(task + 1, tasks));
  };
  threads.run(tasks, merge);
  x_.swap(next_x_);
  y_.swap(next_y_);
  id_.swap(next_id_);
  strip_begin_.swap(next_begin_);
}

// Copies the agents' new positions into their slots and lists those that changed strip.
// The agents are read in sorted order, so their positions (by id) are scattered in memory:
// they are prefetched kLookAhead slots ahead (the padding after the last strip keeps the
// look-ahead inside the arrays).
void SortedStrips::refresh_strips(std::span<const Vec2> positions, int task, int first, int last) {
  std::vector<Arrival>& leavers = leavers_[static_cast<std::size_t>(task)];
  leavers.clear();
  const Layout layout = layout_;
  const std::uint32_t* id = id_.data();
  double* x = x_.data();
  double* y = y_.data();
  const Vec2* position = positions.data();
  const auto last_agent = static_cast<std::uint32_t>(positions.size() - 1);
  for (int s = first; s < last; ++s) {
    const std::uint32_t begin = strip_first(s), end = strip_sentinel(s);
    const std::size_t leavers_before = leavers.size();
    for (std::uint32_t k = begin; k < end; ++k) {
      __builtin_prefetch(position + std::min(id[k + kLookAhead], last_agent));
      const Vec2 p = position[id[k]];
      x[k] = p.x;
      y[k] = p.y;
      const std::uint32_t strip = layout.strip_of(p.y);
      if (strip != static_cast<std::uint32_t>(s)) leavers.push_back({p.x, p.y, id[k], strip, k});
    }
    departures_[static_cast<std::size_t>(s)] =
        static_cast<std::uint32_t>(leavers.size() - leavers_before);
  }
}

// Groups the agents that changed strip by the strip they entered, sorted by (x, id) within
// each, and sets the strips' new bounds.
void SortedStrips::sort_arrivals(int tasks) {
  const auto strips = static_cast<std::size_t>(strips_);
  // Counting sort: counts at each strip's end bound, then handed out downwards.
  std::fill(arrival_begin_.begin(), arrival_begin_.end(), 0);
  std::size_t total = 0;
  for (int task = 0; task < tasks; ++task) {
    for (const Arrival& a : leavers_[static_cast<std::size_t>(task)]) ++arrival_begin_[a.strip + 1];
    total += leavers_[static_cast<std::size_t>(task)].size();
  }
  for (std::size_t s = 1; s <= strips; ++s) arrival_begin_[s] += arrival_begin_[s - 1];
  arrivals_.resize(total);
  for (int task = 0; task < tasks; ++task) {
    for (const Arrival& a : leavers_[static_cast<std::size_t>(task)]) {
      arrivals_[--arrival_begin_[a.strip + 1]] = a;
    }
  }
  // Each strip's arrivals now start at arrival_begin_[s + 1]; shift the bounds back.
  std::uint32_t base = 0;
  for (std::size_t s = 0; s < strips; ++s) {
    const std::uint32_t first = arrival_begin_[s + 1];
    const std::uint32_t last = s + 1 < strips ? arrival_begin_[s + 2] : total;
    arrival_begin_[s] = first;
    std::sort(arrivals_.begin() + first, arrivals_.begin() + last,
              [](const Arrival& a, const Arrival& b) {
                return a.x < b.x || (a.x == b.x && a.id < b.id);
              });
    next_begin_[s] = base;
    const std::uint32_t stayed =
        strip_sentinel(static_cast<int>(s)) - strip_first(static_cast<int>(s)) - departures_[s];
    base += stayed + (last - first) + 1;  // and the sentinel
  }
  arrival_begin_[strips] = static_cast<std::uint32_t>(total);
  next_begin_[strips] = base;
}

// Copies strips [first, last) to the other buffer: each strip's remaining agents in their
// order, its arrivals merged in by x. The loop keeps its cursors in locals: stores through
// the arrays could otherwise alias them, as far as the compiler knows, and force reloads.
void SortedStrips::merge_strips(int task, int first, int last) {
  const double* x = x_.data();
  const double* y = y_.data();
  const std::uint32_t* id = id_.data();
  double* out_x = next_x_.data();
  double* out_y = next_y_.data();
  std::uint32_t* out_id = next_id_.data();
  const std::vector<Arrival>& leavers = leavers_[static_cast<std::size_t>(task)];
  const Arrival* leaver = leavers.data();
  const Arrival* leavers_end = leaver + leavers.size();
  std::uint32_t next_gap = leaver == leavers_end ? kNoAgent : leaver->slot;
  for (int s = first; s < last; ++s) {
    const std::uint32_t begin = next_begin_[static_cast<std::size_t>(s)];
    std::uint32_t end = begin;
    double largest_x = -kInfinity;
    auto put = [&](double px, double py, std::uint32_t pid) {
      if (px < largest_x) return insert_back(out_x, out_y, out_id, begin, end++, px, py, pid);
      out_x[end] = px;
      out_y[end] = py;
      out_id[end] = pid;
      largest_x = px;
      ++end;
    };
    const Arrival* arrival = arrivals_.data() + arrival_begin_[static_cast<std::size_t>(s)];
    const Arrival* arrivals_end =
        arrivals_.data() + arrival_begin_[static_cast<std::size_t>(s) + 1];
    for (std::uint32_t k = strip_first(s), strip_end = strip_sentinel(s); k < strip_end; ++k) {
      if (k == next_gap) {
        next_gap = ++leaver == leavers_end ? kNoAgent : leaver->slot;
        continue;
      }
      const double xk = x[k];
      for (; arrival != arrivals_end && arrival->x < xk; ++arrival) {
        put(arrival->x, arrival->y, arrival->id);
      }
      put(xk, y[k], id[k]);
    }
    for (; arrival != arrivals_end; ++arrival) put(arrival->x, arrival->y, arrival->id);
    out_x[end] = kInfinity;  // the sentinel
    out_y[end] = 0.0;
    out_id[end] = kNoAgent;
  }
}

}  // namespace swarmagg
