#include "control_interface/neighbour_lists.hpp"

#include <algorithm>
#include <cstring>

namespace swarmagg {
namespace {

// How many pairs (or agents) ahead each pass prefetches: enough to cover a miss to memory
// with the work of the pairs in between.
constexpr std::size_t kPrefetchAhead = 16;

// Evaluated whole (no short circuit), so that it can decide without a branch.
bool nearer(const Neighbour& a, const Neighbour& b) {
  return (a.distance < b.distance) | ((a.distance == b.distance) & (a.id < b.id));
}

// Lists hold a handful of neighbours, where insertion sort beats std::sort's set-up.
void sort_by_distance(Neighbour* first, Neighbour* last) {
  for (Neighbour* i = first + 1; i < last; ++i) {
    const Neighbour moving = *i;
    Neighbour* j = i;
    for (; j > first && nearer(moving, *(j - 1)); --j) *j = *(j - 1);
    *j = moving;
  }
}

// In place; returns the sum. Unrolled, as the running total's chain of additions is the
// loop's only dependency and most counts are zero.
std::uint32_t inclusive_prefix_sum(std::uint32_t* values, std::size_t n) {
  std::uint32_t total = 0;
  const std::size_t whole = n - n % 4;
  std::size_t a = 0;
  for (; a < whole; a += 4) {
    const std::uint32_t v0 = values[a], v1 = values[a + 1], v2 = values[a + 2], v3 = values[a + 3];
    values[a] = total += v0;
    values[a + 1] = total += v1;
    values[a + 2] = total += v2;
    values[a + 3] = total += v3;
  }
  for (; a < n; ++a) values[a] = total += values[a];
  return total;
}

// Most lists that need sorting hold two, whose order is a coin toss: those are ordered
// without a branch (both rewritten, the nearer first).
void sort_short_by_distance(Neighbour* first, Neighbour* last) {
  if (last - first != 2) {
    sort_by_distance(first, last);
    return;
  }
  const std::size_t swapped = nearer(first[1], first[0]);
  const Neighbour nearest = first[swapped];
  const Neighbour other = first[1 - swapped];
  first[0] = nearest;
  first[1] = other;
}

// The place kPrefetchAhead on from k, within the first `size` (the last places prefetch
// the last entry again, which costs nothing).
std::size_t ahead(std::size_t k, std::size_t size) {
  return std::min(k + kPrefetchAhead, size - 1);
}

// Counts each agent's pairs into count[agent], copies the pairs and lists the agents whose
// count reached 2 in `crowded`; returns how many.
std::size_t count_pair_ends(std::span<const ClosePair> pairs, std::uint32_t* count, ClosePair* copy,
                            AgentId* crowded) {
  std::size_t crowded_count = 0;
  const std::size_t n = pairs.size();
  const ClosePair* pair = pairs.data();
  for (std::size_t k = 0; k < n; ++k) {
    const ClosePair& next = pair[ahead(k, n)];
    __builtin_prefetch(count + next.i, 1);
    __builtin_prefetch(count + next.j, 1);
    const ClosePair& p = pair[k];
    copy[k] = p;
    crowded[crowded_count] = p.i;
    crowded_count += ++count[p.i] == 2;
    crowded[crowded_count] = p.j;
    crowded_count += ++count[p.j] == 2;
  }
  return crowded_count;
}

// Places both ends of every pair at its agent's end (end[agent], decremented: it ends as the
// agent's start), then sorts the lists of the crowded agents.
void place_and_sort(std::span<const ClosePair> pairs, std::uint32_t* end, Neighbour* items,
                    std::span<const AgentId> crowded) {
  const std::size_t n = pairs.size();
  const ClosePair* pair = pairs.data();
  for (std::size_t k = 0; k < n; ++k) {
    // Two stages: the ends of the pair twice as far ahead, then the items at the ends of
    // the pair ahead (next to the slots its decrements will fill).
    const ClosePair& later = pair[ahead(k + kPrefetchAhead, n)];
    __builtin_prefetch(end + later.i, 1);
    __builtin_prefetch(end + later.j, 1);
    const ClosePair& next = pair[ahead(k, n)];
    __builtin_prefetch(items + end[next.i], 1);
    __builtin_prefetch(items + end[next.j], 1);
    const ClosePair& p = pair[k];
    items[--end[p.i]] = {p.j, p.offset, p.distance};
    items[--end[p.j]] = {p.i, -p.offset, p.distance};
  }
  const std::uint32_t* begin = end;  // placing left each agent's start there
  for (std::size_t k = 0; k < crowded.size(); ++k) {
    __builtin_prefetch(begin + crowded[ahead(k + kPrefetchAhead, crowded.size())]);
    __builtin_prefetch(items + begin[crowded[ahead(k, crowded.size())]], 1);
    const AgentId a = crowded[k];
    sort_short_by_distance(items + begin[a], items + begin[a + 1]);
  }
}

}  // namespace

void NeighbourLists::close_agent(AgentId agent) {
  sort_by_distance(items_.data() + begin_[agent], items_.data() + items_.size());
  begin_[agent + 1] = static_cast<std::uint32_t>(items_.size());
  for (const Neighbour& nb : of(agent)) {
    if (nb.id > agent) pairs_.push_back({agent, nb.id, nb.offset, nb.distance});
  }
}

// Counting sort of the pair ends by agent. Each agent's count goes to begin_[agent]; the
// inclusive prefix sum turns it into the agent's end, and placing items by decrementing it
// leaves its start. Only agents with two or more neighbours need sorting; the sorted lists
// do not depend on the order the pairs came in (distance, then id, orders them totally).
// An agent's count reaching 2 is rare and unpredictable, so the crowded list is written
// without a branch (every end written, only the second arrival counted).
//
// The pairs come in strip order (or, from the kinematic engine's Verlet list, by lower id, the
// higher at random), so their agents' counts and lists lie at random in memory:
// in large swarms nearly every access misses the cache (at 10^4 agents, the first level).
// Each pass therefore prefetches what the pair (or crowded agent) kPrefetchAhead places on
// will touch, so that many misses are in flight at once instead of one after another. One
// step of the bench world: 0.051 -> 0.046 ms at 10^4 agents, 18-20 -> 12 ms at 10^6
// (thread CPU time, best of many, same pairs; callgrind counts more instructions, as the
// prefetches are some). The passes work through local pointers: through the members, every
// store could alias them, as far as the compiler knows, and force reloads.
//
// The same pairs in the same order, bit for bit, give the same lists: those are kept, with
// their generation, so that whatever was computed from them stays too (a world where only
// agents far from everybody move changes no list). ClosePair has no padding, so comparing
// bytes compares every field's bits.
void NeighbourLists::assign_from_pairs(std::size_t agent_count, std::span<const ClosePair> pairs) {
  static_assert(sizeof(ClosePair) == 2 * sizeof(AgentId) + sizeof(Vec2) + sizeof(double));
  if (agent_count == agent_count_of_pairs_ && pairs.size() == pairs_.size() &&
      std::memcmp(pairs.data(), pairs_.data(), pairs.size_bytes()) == 0)
    return;
  ++generation_;
  if (agent_count == agent_count_of_pairs_ && remeasure(pairs)) return;
  agent_count_of_pairs_ = agent_count;
  begin_.assign(agent_count + 1, 0);
  pairs_.resize(pairs.size());
  crowded_.resize(agent_count + 1);  // every agent once, plus the slot written and not counted
  resorted_.resize(agent_count, 0);  // remeasure's, sized here so that it never allocates later
  const std::size_t crowded_count =
      count_pair_ends(pairs, begin_.data(), pairs_.data(), crowded_.data());
  const std::uint32_t total = inclusive_prefix_sum(begin_.data(), agent_count);
  begin_[agent_count] = total;
  items_.resize(total);
  place_and_sort(pairs, begin_.data(), items_.data(),
                 std::span<const AgentId>(crowded_.data(), crowded_count));
}

// The same pairs in the same order, some of them measured anew (agents moved, none came into
// or left another's sensing radius: a step in which a few agents move near packed
// aggregates): each changed pair's two items are overwritten where they lie, and the lists
// holding them sorted again. Lists are ordered totally (distance, then id), so they come out
// as a full rebuild would make them. False, with nothing changed, when the pairs differ.
bool NeighbourLists::remeasure(std::span<const ClosePair> pairs) {
  const std::size_t n = pairs.size();
  if (n != pairs_.size()) return false;
  for (std::size_t k = 0; k < n; ++k) {
    if ((pairs[k].i != pairs_[k].i) | (pairs[k].j != pairs_[k].j)) return false;
  }
  // The agents whose lists changed, each once in crowded_ (marked in resorted_, all clear
  // between calls; both sized by the rebuild that made these lists).
  std::size_t changed = 0;
  auto overwrite = [&](AgentId agent, const Neighbour& item) {
    for (Neighbour& nb :
         std::span<Neighbour>(items_.data() + begin_[agent], items_.data() + begin_[agent + 1])) {
      if (nb.id == item.id) nb = item;
    }
    crowded_[changed] = agent;
    changed += resorted_[agent] == 0;
    resorted_[agent] = 1;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const ClosePair& p = pairs[k];
    if (std::memcmp(&p, &pairs_[k], sizeof(ClosePair)) == 0) continue;
    pairs_[k] = p;
    overwrite(p.i, {p.j, p.offset, p.distance});
    overwrite(p.j, {p.i, -p.offset, p.distance});
  }
  for (std::size_t k = 0; k < changed; ++k) {
    const AgentId a = crowded_[k];
    resorted_[a] = 0;
    sort_by_distance(items_.data() + begin_[a], items_.data() + begin_[a + 1]);
  }
  return true;
}

}  // namespace swarmagg
