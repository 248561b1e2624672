#include "control_interface/neighbour_lists.hpp"

namespace swarmagg {
namespace {

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
void NeighbourLists::assign_from_pairs(std::size_t agent_count, std::span<const ClosePair> pairs) {
  begin_.assign(agent_count + 1, 0);
  pairs_.resize(pairs.size());
  crowded_.resize(agent_count + 1);  // every agent once, plus the slot written and not counted
  std::uint32_t* count = begin_.data();
  AgentId* crowded = crowded_.data();
  std::size_t crowded_count = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const ClosePair& p = pairs[k];
    pairs_[k] = p;
    crowded[crowded_count] = p.i;
    crowded_count += ++count[p.i] == 2;
    crowded[crowded_count] = p.j;
    crowded_count += ++count[p.j] == 2;
  }
  const std::uint32_t total = inclusive_prefix_sum(count, agent_count);
  begin_[agent_count] = total;
  items_.resize(total);
  for (const ClosePair& p : pairs) {
    items_[--begin_[p.i]] = {p.j, p.offset, p.distance};
    items_[--begin_[p.j]] = {p.i, -p.offset, p.distance};
  }
  for (std::size_t k = 0; k < crowded_count; ++k) {
    const AgentId a = crowded[k];
    sort_short_by_distance(items_.data() + begin_[a], items_.data() + begin_[a + 1]);
  }
}

}  // namespace swarmagg
