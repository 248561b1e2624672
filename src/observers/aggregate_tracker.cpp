#include "observers/aggregate_tracker.hpp"

#include <algorithm>

namespace swarmagg {
namespace {

// Lists the waiting agents in index order into `waiting` (kept at full length) and returns
// how many there are. Without branches: every index is written, only a waiting one counts,
// since waiting and moving agents alternate unpredictably along the indices.
std::size_t list_waiting(std::span<const AgentState> state, AgentArray<std::uint32_t>& waiting) {
  const std::size_t n = state.size();
  if (waiting.size() != n) waiting.resize(n);
  std::uint32_t* out = waiting.data();
  const AgentState* s = state.data();
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    out[count] = static_cast<std::uint32_t>(i);
    count += s[i] == AgentState::Wait;
  }
  return count;
}

}  // namespace

void AggregateTracker::update(const NeighbourLists& neighbours, const SwarmState& swarm,
                              double detection_radius, AggregateLinks links) {
  const std::size_t n = swarm.size();
  // Only waiting agents can be in aggregates; the union-find touches nothing else.
  const std::span<const std::uint32_t> waiting(waiting_.data(),
                                               list_waiting(swarm.state, waiting_));
  sets_.reserve_elements(n);
  index_of_root_.resize(n);
  for (const std::uint32_t i : waiting) {
    sets_.make_set(i);
    index_of_root_[i] = -1;
  }
  for (const std::uint32_t i : waiting) {
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
  label_components(n, waiting);
}

// Only the agents labelled last time are unlabelled (not all n), so a step costs in
// proportion to the waiting agents.
void AggregateTracker::label_components(std::size_t n, std::span<const std::uint32_t> waiting) {
  if (aggregate_of_.size() != n) {
    aggregate_of_.assign(n, -1);
    size_of_agent_.assign(n, 0);
    // Their bounds (every agent labelled, aggregates of two), so no step ever grows them.
    labelled_.reserve(n);
    sizes_.reserve(n / 2);
  } else {
    for (const std::uint32_t i : labelled_) {
      aggregate_of_[i] = -1;
      size_of_agent_[i] = 0;
    }
  }
  labelled_.clear();
  sizes_.clear();
  largest_ = 0;
  for (const std::uint32_t i : waiting) {
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
    labelled_.push_back(i);
  }
  count_ = static_cast<int>(sizes_.size());
}

}  // namespace swarmagg
