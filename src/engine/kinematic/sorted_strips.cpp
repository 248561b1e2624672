#include "engine/kinematic/sorted_strips.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Agents per block: enough that blocks are few, few enough that sorting within one is cheap.
constexpr double kAgentsPerBlock = 8.0;
// Agents per task below which waking another thread costs more than it saves.
constexpr std::size_t kAgentsPerTask = 16384;

int tasks_for(std::size_t agents, int strips, const StepThreads& threads) {
  const auto by_work = static_cast<int>(agents / kAgentsPerTask);
  return std::max(1, std::min({threads.size(), by_work, strips}));
}

}  // namespace

bool SortedStrips::fits(const ArenaGeometry& arena, double window) {
  return std::floor(arena.height() / window) >= 3.0 && arena.width() >= 3.0 * window;
}

SortedStrips::Layout SortedStrips::layout_for(const ArenaGeometry& arena, double window,
                                              std::size_t agents) {
  Layout layout;
  layout.strips = static_cast<int>(std::floor(arena.height() / window));
  const double strip_height = arena.height() / layout.strips;
  const double per_strip = static_cast<double>(agents) / layout.strips;
  const double blocks = std::floor(per_strip / kAgentsPerBlock);
  // Blocks narrower than a window would only add cells to count.
  const double widest = std::floor(arena.width() / std::min(window, strip_height));
  layout.blocks = static_cast<int>(std::clamp(std::min(blocks, widest), 1.0, 65536.0));
  layout.strip_scale = layout.strips / arena.height();
  layout.block_scale = layout.blocks / arena.width();
  return layout;
}

bool SortedStrips::same_layout(const ArenaGeometry& arena, double window,
                               std::size_t agents) const {
  return strips_ > 0 && window == window_ && agents == agents_ && arena.width() == arena_.width() &&
         arena.height() == arena_.height() && arena.torus() == arena_.torus() &&
         layout_for(arena, window, agents) == layout_;
}

void SortedStrips::update(const ArenaGeometry& arena, double window,
                          std::span<const Vec2> positions, StepThreads& threads) {
  if (same_layout(arena, window, positions.size())) return restrip(positions, threads);
  arena_ = arena;
  window_ = window;
  layout_ = layout_for(arena, window, positions.size());
  strips_ = layout_.strips;
  agents_ = positions.size();
  sort_from_scratch(positions);
}

void SortedStrips::sort_from_scratch(std::span<const Vec2> positions) {
  const std::size_t n = positions.size();
  const std::size_t cells = static_cast<std::size_t>(strips_) * layout_.blocks;
  const std::size_t slots = n + static_cast<std::size_t>(strips_);
  const std::size_t padded = slots + kLookAhead;
  task_cursor_.resize(1);
  std::vector<std::uint32_t>& counts = task_cursor_[0];
  counts.assign(cells, 0);
  new_cell_.resize(slots);
  for (std::size_t i = 0; i < n; ++i) {
    new_cell_[i] = layout_.cell_of(positions[i]);
    ++counts[new_cell_[i]];
  }
  prefix_counts(1);
  cell_begin_.swap(next_begin_);
  // The padding after the last strip reads as sentinels.
  x_.assign(padded, kInfinity);
  y_.assign(padded, 0.0);
  id_.assign(padded, kNoAgent);
  for (std::size_t i = 0; i < n; ++i) id_[counts[new_cell_[i]]++] = static_cast<std::uint32_t>(i);
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
  close_strips();
  new_x_.resize(slots);
  new_y_.resize(slots);
  new_id_.resize(slots);
}

// next_begin_ from the per-task counts, a strip's sentinel after its last block; each
// task's counts become its cursors, so tasks place their slots after earlier tasks'.
void SortedStrips::prefix_counts(int tasks) {
  const std::size_t cells = static_cast<std::size_t>(strips_) * layout_.blocks;
  next_begin_.resize(cells + 1);
  std::uint32_t base = 0;
  std::size_t cell = 0;
  for (int s = 0; s < strips_; ++s) {
    for (int b = 0; b < layout_.blocks; ++b, ++cell) {
      next_begin_[cell] = base;
      for (int task = 0; task < tasks; ++task) {
        const std::uint32_t here = task_cursor_[task][cell];
        task_cursor_[task][cell] = base;
        base += here;
      }
    }
    ++base;  // the sentinel
  }
  next_begin_[cells] = base;
}

void SortedStrips::close_strips() {
  for (int s = 0; s < strips_; ++s) {
    const std::uint32_t sentinel = strip_sentinel(s);
    x_[sentinel] = kInfinity;
    y_[sentinel] = 0.0;
    id_[sentinel] = kNoAgent;
  }
}

// A stable counting sort by cell in the previous slot order, in parallel over contiguous
// strip ranges: each task counts its slots by destination cell, and the prefix over (cell,
// task) gives every task its own cursors, so the result is exactly the sequential one.
// Then an insertion sort by x within strips.
void SortedStrips::restrip(std::span<const Vec2> positions, StepThreads& threads) {
  const std::size_t cells = static_cast<std::size_t>(strips_) * layout_.blocks;
  const int tasks = tasks_for(agents_, strips_, threads);
  task_cursor_.resize(static_cast<std::size_t>(tasks));
  for (auto& cursor : task_cursor_) cursor.assign(cells, 0);
  auto gather = [&](int task) {
    gather_strips(positions, task, first_strip(task, tasks), first_strip(task + 1, tasks));
  };
  threads.run(tasks, gather);
  prefix_counts(tasks);
  auto scatter = [&](int task) {
    scatter_strips(task, first_strip(task, tasks), first_strip(task + 1, tasks));
  };
  threads.run(tasks, scatter);
  cell_begin_.swap(next_begin_);
  close_strips();
  auto sort = [&](int task) {
    sort_strips_by_x(first_strip(task, tasks), first_strip(task + 1, tasks));
  };
  threads.run(tasks, sort);
}

// The agents are read in sorted order, so their positions (by id) are scattered in memory:
// they are prefetched a little ahead (the padding after the last strip keeps the look-ahead
// inside the arrays). The loops copy members into locals: stores through the arrays could
// otherwise alias them (as far as the compiler knows) and force reloads.
void SortedStrips::gather_strips(std::span<const Vec2> positions, int task, int first, int last) {
  const Layout layout = layout_;
  std::uint32_t* counts = task_cursor_[task].data();
  const std::uint32_t* id = id_.data();
  const Vec2* position = positions.data();
  const auto last_agent = static_cast<std::uint32_t>(positions.size() - 1);
  std::uint32_t* new_cell = new_cell_.data();
  double* new_x = new_x_.data();
  double* new_y = new_y_.data();
  std::uint32_t* new_id = new_id_.data();
  for (int s = first; s < last; ++s) {
    const std::uint32_t begin = strip_first(s), end = strip_sentinel(s);
    for (std::uint32_t k = begin; k < end; ++k) {
      __builtin_prefetch(position + std::min(id[k + kLookAhead], last_agent));
      const std::uint32_t agent = id[k];
      const Vec2 p = position[agent];
      const std::uint32_t cell = layout.cell_of(p);
      new_cell[k] = cell;
      new_x[k] = p.x;
      new_y[k] = p.y;
      new_id[k] = agent;
      ++counts[cell];
    }
  }
}

void SortedStrips::scatter_strips(int task, int first, int last) {
  std::uint32_t* cursor = task_cursor_[task].data();
  const std::uint32_t* new_cell = new_cell_.data();
  const double* new_x = new_x_.data();
  const double* new_y = new_y_.data();
  const std::uint32_t* new_id = new_id_.data();
  double* x = x_.data();
  double* y = y_.data();
  std::uint32_t* id = id_.data();
  // The old strip bounds: cell_begin_ is replaced only after every task has scattered.
  for (int s = first; s < last; ++s) {
    const std::uint32_t strip_begin = strip_first(s), strip_end = strip_sentinel(s);
    for (std::uint32_t k = strip_begin; k < strip_end; ++k) {
      const std::uint32_t slot = cursor[new_cell[k]]++;
      x[slot] = new_x[k];
      y[slot] = new_y[k];
      id[slot] = new_id[k];
    }
  }
}

void SortedStrips::sort_strips_by_x(int first, int last) {
  double* x = x_.data();
  double* y = y_.data();
  std::uint32_t* id = id_.data();
  for (int s = first; s < last; ++s) {
    const std::uint32_t begin = strip_first(s), end = strip_sentinel(s);
    if (begin == end) continue;
    double previous = x[begin];
    for (std::uint32_t k = begin + 1; k < end; ++k) {
      const double xk = x[k];
      if (!(xk < previous)) {
        previous = xk;
        continue;
      }
      // Out of order (an agent overtook another in x): move it back to its place.
      const double yk = y[k];
      const std::uint32_t idk = id[k];
      std::uint32_t j = k;
      do {
        x[j] = x[j - 1];
        y[j] = y[j - 1];
        id[j] = id[j - 1];
        --j;
      } while (j > begin && xk < x[j - 1]);
      x[j] = xk;
      y[j] = yk;
      id[j] = idk;
    }
  }
}

}  // namespace swarmagg
