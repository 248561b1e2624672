#include "observers/aggregate_tracker.hpp"

#include <algorithm>

namespace swarmagg {

void AggregateTracker::update(const NeighbourLists& neighbours, const SwarmState& swarm,
                              double detection_radius, AggregateLinks links) {
  const std::size_t n = swarm.size();
  // Only waiting agents can be in aggregates; the union-find touches nothing else.
  waiting_.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (swarm.state[i] == AgentState::Wait) waiting_.push_back(i);
  }
  sets_.reserve_elements(n);
  index_of_root_.resize(n);
  for (const std::uint32_t i : waiting_) {
    sets_.make_set(i);
    index_of_root_[i] = -1;
  }
  for (const std::uint32_t i : waiting_) {
    if (links == AggregateLinks::PartnersOnly) {
      const std::int32_t p = swarm.partner[i];
      if (p != kNoPartner && swarm.state[p] == AgentState::Wait) sets_.unite(i, p);
      continue;
    }
    for (const Neighbour& nb : neighbours.of(i)) {
      if (nb.distance > detection_radius) break;  // nearest first
      if (nb.id > i && swarm.state[nb.id] == AgentState::Wait) sets_.unite(i, nb.id);
    }
  }
  label_components(n);
}

void AggregateTracker::label_components(std::size_t n) {
  aggregate_of_.assign(n, -1);
  size_of_agent_.assign(n, 0);
  sizes_.clear();
  largest_ = 0;
  for (const std::uint32_t i : waiting_) {
    const std::uint32_t root = sets_.find(i);
    const auto size = static_cast<std::int32_t>(sets_.size_of(root));
    if (size < 2) continue;
    if (index_of_root_[root] < 0) {
      index_of_root_[root] = static_cast<std::int32_t>(sizes_.size());
      sizes_.push_back(size);
      largest_ = std::max(largest_, static_cast<int>(size));
    }
    aggregate_of_[i] = index_of_root_[root];
    size_of_agent_[i] = size;
  }
  count_ = static_cast<int>(sizes_.size());
}

}  // namespace swarmagg
