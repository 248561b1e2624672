#include "control_interface/neighbour_lists.hpp"

namespace swarmagg {
namespace {

bool nearer(const Neighbour& a, const Neighbour& b) {
  return a.distance < b.distance || (a.distance == b.distance && a.id < b.id);
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

}  // namespace

void NeighbourLists::close_agent(AgentId agent) {
  sort_by_distance(items_.data() + begin_[agent], items_.data() + items_.size());
  begin_[agent + 1] = static_cast<std::uint32_t>(items_.size());
}

// Counting sort of the pair ends by agent. Each agent's count goes to begin_[agent]; the
// inclusive prefix sum turns it into the agent's end, and placing items by decrementing it
// leaves its start. Only agents with two or more neighbours need sorting; the sorted lists
// do not depend on the order the pairs came in (distance, then id, orders them totally).
void NeighbourLists::assign_from_pairs(std::size_t agent_count, std::span<const ClosePair> pairs) {
  begin_.assign(agent_count + 1, 0);
  crowded_.clear();
  for (const ClosePair& p : pairs) {
    if (++begin_[p.i] == 2) crowded_.push_back(p.i);
    if (++begin_[p.j] == 2) crowded_.push_back(p.j);
  }
  std::uint32_t total = 0;
  for (std::size_t a = 0; a < agent_count; ++a) {
    total += begin_[a];
    begin_[a] = total;
  }
  begin_[agent_count] = total;
  items_.resize(total);
  for (const ClosePair& p : pairs) {
    items_[--begin_[p.i]] = {p.j, p.offset, p.distance};
    items_[--begin_[p.j]] = {p.i, -p.offset, p.distance};
  }
  for (const AgentId a : crowded_) {
    sort_by_distance(items_.data() + begin_[a], items_.data() + begin_[a + 1]);
  }
}

}  // namespace swarmagg
