#include "engine/neighbour_lists.hpp"

#include <algorithm>

namespace swarmagg {

void NeighbourLists::close_agent(AgentId agent) {
  const auto first = items_.begin() + begin_[agent];
  std::sort(first, items_.end(), [](const Neighbour& a, const Neighbour& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.id < b.id);
  });
  begin_[agent + 1] = static_cast<std::uint32_t>(items_.size());
}

}  // namespace swarmagg
