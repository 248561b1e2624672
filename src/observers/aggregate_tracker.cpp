#include "observers/aggregate_tracker.hpp"

#include <algorithm>
#include <cstring>

#include "core/agents_in_state.hpp"

namespace swarmagg {
namespace {

// Whole arrays of plain values, compared as bytes (a world at rest compares its states every
// step).
template <typename A, typename B>
bool same_bytes(const A& a, const B& b) {
  static_assert(sizeof(*a.data()) == sizeof(*b.data()));
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(*a.data())) == 0;
}

}  // namespace

bool AggregateTracker::same_links(const NeighbourLists& neighbours, const SwarmState& swarm,
                                  double radius, AggregateLinks links) {
  const bool partners = links == AggregateLinks::PartnersOnly;
  const bool same = lists_ == &neighbours && generation_ == neighbours.generation() &&
                    links_ == links && radius_ == radius && same_bytes(states_, swarm.state) &&
                    (!partners || same_bytes(partners_, swarm.partner));
  if (same) return true;
  // Remembering costs copies, which pay only in a world at rest (lists that stayed since the
  // last update); in a moving world nothing is remembered.
  const bool lists_stayed =
      seen_lists_ == &neighbours && seen_generation_ == neighbours.generation();
  seen_lists_ = &neighbours;
  seen_generation_ = neighbours.generation();
  lists_ = lists_stayed ? &neighbours : nullptr;
  if (!lists_stayed) return false;
  generation_ = neighbours.generation();
  links_ = links;
  radius_ = radius;
  states_.assign(swarm.state.begin(), swarm.state.end());
  if (partners) partners_.assign(swarm.partner.begin(), swarm.partner.end());
  return false;
}

void AggregateTracker::update(const NeighbourLists& neighbours, const SwarmState& swarm,
                              double detection_radius, AggregateLinks links) {
  if (same_links(neighbours, swarm, detection_radius, links)) return;
  const std::size_t n = swarm.size();
  // Only waiting agents can be in aggregates; the union-find touches nothing else.
  if (waiting_.size() != n) waiting_.resize(n);
  const std::span<const std::uint32_t> waiting(
      waiting_.data(), list_agents_in_state(swarm.state, AgentState::Wait, waiting_.data()));
  sets_.reserve_elements(n);
  for (const std::uint32_t i : waiting) sets_.make_set(i);
  const AgentState* state = swarm.state.data();
  if (links == AggregateLinks::PartnersOnly) {
    for (const std::uint32_t i : waiting) {
      const std::int32_t p = swarm.partner[i];
      if (p != kNoPartner && state[p] == AgentState::Wait) sets_.unite(i, p);
    }
  } else {
    // Each perceived pair once, in one flat pass: walking every waiting agent's short list
    // instead costs a mispredicted loop exit per agent. Nearly every pair links two waiting
    // agents (moving agents that perceive one stop), so the one branch is well predicted.
    for (const ClosePair& p : neighbours.pairs()) {
      const bool linked = (p.distance <= detection_radius) & (state[p.i] == AgentState::Wait) &
                          (state[p.j] == AgentState::Wait);
      if (linked) sets_.unite(p.i, p.j);
    }
  }
  label_components(n, waiting);
}

// Only the agents labelled last time are unlabelled (not all n), so a step costs in
// proportion to the waiting agents. Labelling itself has no branch: waiting agents in index
// order each reach their root (their aggregate's lowest agent) in one step, a root that
// heads an aggregate opens the next index, and the others copy their root's.
void AggregateTracker::label_components(std::size_t n, std::span<const std::uint32_t> waiting) {
  if (aggregate_of_.size() != n) {
    aggregate_of_.assign(n, -1);
    size_of_agent_.assign(n, 0);
    // Their bounds: every agent labelled, every aggregate of two (plus the slot that is
    // written and not counted).
    labelled_.resize(n);
    sizes_.resize(n / 2 + 1);
  } else {
    for (const std::uint32_t i : aggregated_agents()) {
      aggregate_of_[i] = -1;
      size_of_agent_[i] = 0;
    }
  }
  std::int32_t* aggregate_of = aggregate_of_.data();
  std::int32_t* size_of_agent = size_of_agent_.data();
  std::int32_t* sizes = sizes_.data();
  std::uint32_t* labelled = labelled_.data();
  std::int32_t count = 0;
  std::size_t labelled_count = 0;
  for (const std::uint32_t i : waiting) {
    const std::uint32_t root = sets_.settle(i);
    const auto size = static_cast<std::int32_t>(sets_.size_of_root(root));
    const std::int32_t aggregated = size >= 2;
    const std::int32_t heads = aggregated & static_cast<std::int32_t>(root == i);
    sizes[count] = size;
    // A root alone keeps its -1; any other agent's root is lower, so already labelled. By
    // masks, as a compiler turns a conditional choice here back into a branch.
    const std::int32_t new_label = -heads;
    aggregate_of[i] = (count & new_label) | (aggregate_of[root] & ~new_label);
    count += heads;
    size_of_agent[i] = size & -aggregated;
    labelled[labelled_count] = i;
    labelled_count += static_cast<std::size_t>(aggregated);
  }
  count_ = count;
  labelled_count_ = labelled_count;
  largest_ = count == 0 ? 0 : *std::max_element(sizes, sizes + count);
}

void AggregateTracker::members_of(std::uint32_t agent, std::vector<std::uint32_t>& members) const {
  members.clear();
  std::uint32_t member = agent;
  do {
    members.push_back(member);
    member = sets_.next(member);
  } while (member != agent);
  std::sort(members.begin(), members.end());
}

}  // namespace swarmagg
