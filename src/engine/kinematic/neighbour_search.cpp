#include "engine/kinematic/neighbour_search.hpp"

#include <algorithm>
#include <cmath>

namespace swarmagg {
namespace {

// The strips are searched a hair wider than the reach, so that no pair within the reach is
// lost to rounding in the strip bounds; the exact radii apply to the minimum-image offset.
constexpr double kWindowMargin = 1e-9;

}  // namespace

void NeighbourSearch::find(const ArenaGeometry& arena, std::span<const Vec2> positions,
                           const SearchRadii& radii, StepThreads& threads) {
  radii_ = radii;
  arena_ = arena;
  const double reach = std::max(radii.sensing, radii.pair_reach);
  const double window = reach * (1.0 + kWindowMargin);
  if (!SortedStrips::fits(arena, window)) return scan_small(arena, positions, reach);
  strips_.update(arena, window, positions, threads);
  scan_strips(positions.size(), threads);
}

inline void NeighbourSearch::report(Found& out, std::uint32_t i, std::uint32_t j,
                                    Vec2 offset) const {
  const double d2 = norm2(offset);
  if (radii_.perception && d2 <= radii_.sensing * radii_.sensing) {
    out.close.push_back({i, j, offset, std::sqrt(d2)});
  }
  if (d2 <= radii_.pair_reach * radii_.pair_reach) out.candidates.push_back({i, j, offset});
}

void NeighbourSearch::scan_strips(std::size_t agents, StepThreads& threads) {
  const int tasks = std::max(1, std::min({threads.size(), strips_.strips(),
                                          static_cast<int>(agents / StepThreads::kAgentsPerTask)}));
  if (found_.size() < static_cast<std::size_t>(tasks))
    found_.resize(static_cast<std::size_t>(tasks));
  auto scan_one = [&](int task) { scan_task(task, tasks); };
  threads.run(tasks, scan_one);
  join_tasks(tasks);
}

void NeighbourSearch::scan_task(int task, int tasks) {
  Found& out = found_[static_cast<std::size_t>(task)];
  out.candidates.clear();
  out.close.clear();
  const auto strips = static_cast<std::size_t>(strips_.strips());
  const auto first = static_cast<int>(StepThreads::slice_begin(strips, task, tasks));
  const auto last = static_cast<int>(StepThreads::slice_begin(strips, task + 1, tasks));
  strips_.for_each_candidate(first, last, [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t id_a = strips_.id(a), id_b = strips_.id(b);
    // From the lower id to the higher. Which slot holds it is a coin toss, so the two are
    // ordered by a mask (all ones if b comes first), not by a branch.
    const std::uint32_t b_first = 0u - static_cast<std::uint32_t>(id_b < id_a);
    const std::uint32_t i = id_a ^ ((id_a ^ id_b) & b_first), j = i ^ id_a ^ id_b;
    const std::uint32_t from = a ^ ((a ^ b) & b_first), to = from ^ a ^ b;
    report(out, i, j, arena_.displacement(strips_.position(from), strips_.position(to)));
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

// Worlds too small or narrow for three strips.
void NeighbourSearch::scan_small(const ArenaGeometry& arena, std::span<const Vec2> positions,
                                 double reach) {
  small_world_.reset(arena, reach, positions.size());
  for (const Vec2& p : positions) small_world_.add(p);
  if (found_.empty()) found_.resize(1);
  Found& out = found_[0];
  out.candidates.clear();
  out.close.clear();
  small_world_.for_each_pair(
      [&](std::uint32_t i, std::uint32_t j, Vec2 offset) { report(out, i, j, offset); });
  join_tasks(1);
}

}  // namespace swarmagg
