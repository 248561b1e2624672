#include "engine/neighbour_lists.hpp"


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

void NeighbourLists::assign_from_pairs(std::size_t agent_count, std::span<const ClosePair> pairs) {
  begin_.assign(agent_count + 1, 0);
  for (const ClosePair& p : pairs) {
    ++begin_[p.i + 1];
    ++begin_[p.j + 1];
  }
  for (std::size_t a = 1; a <= agent_count; ++a) begin_[a] += begin_[a - 1];
  items_.resize(begin_[agent_count]);
  cursor_.assign(begin_.begin(), begin_.end() - 1);
  for (const ClosePair& p : pairs) {
    items_[cursor_[p.i]++] = {p.j, p.offset, p.distance};
    items_[cursor_[p.j]++] = {p.i, -p.offset, p.distance};
  }
  for (std::size_t a = 0; a < agent_count; ++a) {
    if (begin_[a + 1] - begin_[a] > 1) {
      sort_by_distance(items_.data() + begin_[a], items_.data() + begin_[a + 1]);
    }
  }
}

}  // namespace swarmagg
