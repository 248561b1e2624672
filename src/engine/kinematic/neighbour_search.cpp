#include "engine/kinematic/neighbour_search.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

// The strips are searched a hair wider than the reach, so that no pair within the reach is
// lost to rounding in the strip bounds; the convention then applies the exact reach.
constexpr double kWindowMargin = 1e-9;
// Agents per task below which waking another thread costs more than it saves.
constexpr std::size_t kAgentsPerTask = 16384;

}  // namespace

NeighbourSearch::Plan NeighbourSearch::plan(const ArenaGeometry& arena, std::size_t agents,
                                            const SearchRadii& radii) {
  radii_ = radii;
  Plan p;
  p.reach = std::max(radii.sensing, radii.pair_reach);
  // Cells much smaller than the spacing between agents cost more to sweep than the
  // distance checks they save (the reference grid's own rule; it fixes the convention).
  const double spacing = std::sqrt(arena.width() * arena.height() /
                                   static_cast<double>(std::max<std::size_t>(1, agents)));
  p.min_cell = std::max(p.reach, 1.2 * spacing);
  convention_ = PairConvention(arena, p.min_cell);
  p.window = p.reach * (1.0 + kWindowMargin);
  p.strips = !convention_.scans_all_pairs() && SortedStrips::fits(arena, p.window);
  return p;
}

void NeighbourSearch::find(const ArenaGeometry& arena, std::span<const Vec2> positions,
                           const SearchRadii& radii, StepThreads& threads) {
  const Plan p = plan(arena, positions.size(), radii);
  if (!p.strips) return scan_grid(arena, positions, p.min_cell, p.reach);
  strips_.update(arena, p.window, positions, threads);
  scan(p, positions.size(), threads);
}

void NeighbourSearch::scan(const Plan& p, std::size_t agents, StepThreads& threads) {
  const int tasks = std::max(
      1, std::min({threads.size(), strips_.strips(), static_cast<int>(agents / kAgentsPerTask)}));
  if (found_.size() < static_cast<std::size_t>(tasks))
    found_.resize(static_cast<std::size_t>(tasks));
  auto scan_one = [&](int task) { scan_task(task, tasks, p.reach); };
  threads.run(tasks, scan_one);
  join_tasks(tasks);
}

void NeighbourSearch::scan_task(int task, int tasks, double reach) {
  Found& out = found_[static_cast<std::size_t>(task)];
  out.candidates.clear();
  out.close.clear();
  const auto strips = static_cast<std::size_t>(strips_.strips());
  const auto first = static_cast<int>(StepThreads::slice_begin(strips, task, tasks));
  const auto last = static_cast<int>(StepThreads::slice_begin(strips, task + 1, tasks));
  const double reach2 = reach * reach;
  const double sense2 = radii_.sensing * radii_.sensing;
  const double pair2 = radii_.pair_reach * radii_.pair_reach;
  const bool perception = radii_.perception;
  strips_.for_each_candidate(first, last, [&](std::uint32_t a, std::uint32_t b) {
    const auto pair = convention_.report(strips_.id(a), strips_.position(a), strips_.id(b),
                                         strips_.position(b), reach2);
    if (!pair) return;
    if (perception && pair->d2 <= sense2) {
      out.close.push_back({pair->i, pair->j, pair->offset, std::sqrt(pair->d2)});
    }
    if (pair->d2 <= pair2) {
      out.candidates.push_back({pair->i, pair->j, pair->offset, pair->rank, pair->a_is_j});
    }
  });
}

void NeighbourSearch::join_tasks(int tasks) {
  if (tasks == 1) {
    candidates_ = found_[0].candidates;
    close_ = found_[0].close;
    return;
  }
  joined_candidates_.clear();
  joined_close_.clear();
  // Inserting the tasks' halves one by one grows the joined buffers to barely the total,
  // so a growing pair count would reallocate them every step: reserve with headroom.
  std::size_t candidates = 0, close = 0;
  for (int task = 0; task < tasks; ++task) {
    candidates += found_[static_cast<std::size_t>(task)].candidates.size();
    close += found_[static_cast<std::size_t>(task)].close.size();
  }
  if (candidates > joined_candidates_.capacity()) joined_candidates_.reserve(2 * candidates);
  if (close > joined_close_.capacity()) joined_close_.reserve(2 * close);
  for (int task = 0; task < tasks; ++task) {
    const Found& f = found_[static_cast<std::size_t>(task)];
    joined_candidates_.insert(joined_candidates_.end(), f.candidates.begin(), f.candidates.end());
    joined_close_.insert(joined_close_.end(), f.close.begin(), f.close.end());
  }
  candidates_ = joined_candidates_;
  close_ = joined_close_;
}

// Small or narrow worlds: the reference grid itself, whose scan order is the convention
// (rank = position in the list).
void NeighbourSearch::scan_grid(const ArenaGeometry& arena, std::span<const Vec2> positions,
                                double min_cell, double reach) {
  grid_.rebuild(arena, min_cell, positions);
  if (found_.empty()) found_.resize(1);
  Found& out = found_[0];
  out.candidates.clear();
  out.close.clear();
  const double sense2 = radii_.sensing * radii_.sensing;
  const double pair2 = radii_.pair_reach * radii_.pair_reach;
  grid_.for_each_close_pair(reach, [&](std::uint32_t i, std::uint32_t j, Vec2 d, double d2) {
    if (radii_.perception && d2 <= sense2) out.close.push_back({i, j, d, std::sqrt(d2)});
    if (d2 <= pair2) {
      out.candidates.push_back({i, j, d, static_cast<std::uint32_t>(out.candidates.size()), false});
    }
  });
  join_tasks(1);
}

}  // namespace swarmagg
