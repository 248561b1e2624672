#include "observers/leave_episodes.hpp"

#include <algorithm>

namespace swarmagg {

LeaveEpisodes::LeaveEpisodes(int agent_count, double detection_radius, const ShapeRules& rules)
    : detection_radius_(detection_radius), rules_(rules) {
  tally_.resize(agent_count);
  open_.reserve(static_cast<std::size_t>(agent_count));  // one attempt per agent at most
  // Room for as many remembered members as there are agents, so that most runs never grow it.
  former_.reserve(static_cast<std::size_t>(agent_count));
  members_.reserve(static_cast<std::size_t>(agent_count));  // the largest aggregate's bound
}

void LeaveEpisodes::observe_decision(const AggregateTracker& aggregates,
                                     const NeighbourLists& neighbours,
                                     std::span<const Vec2> positions,
                                     std::span<const AgentState> state) {
  for (const std::int32_t size : aggregates.sizes()) ++tally_.aggregate_steps_by_size[size];
  end_attempts(neighbours, state);
  start_attempts(aggregates, positions, state);
}

// Every agent in an aggregate was waiting when the decision started, so one now leaving has
// just gone WAIT -> LEAVE.
void LeaveEpisodes::start_attempts(const AggregateTracker& aggregates,
                                   std::span<const Vec2> positions,
                                   std::span<const AgentState> state) {
  for (const AgentId i : aggregates.aggregated_agents()) {
    if (state[i] != AgentState::Leave) continue;
    const std::int32_t aggregate = aggregates.aggregate_of()[i];
    aggregates.members_of(i, members_);
    const std::span<const AgentId> members = members_;
    OpenAttempt attempt;
    attempt.agent = i;
    attempt.size = aggregates.sizes()[static_cast<std::size_t>(aggregate)];
    attempt.rim =
        rules_.rim.on_rim(member_surroundings(i, members, positions, rules_).fellows_within_reach);
    attempt.first = static_cast<std::uint32_t>(former_.size());
    attempt.count = static_cast<std::uint32_t>(members.size() - 1);
    for (const AgentId j : members) {
      if (j != i) former_.push_back(j);
    }
    open_.push_back(attempt);
    tally_.attempts.count(attempt.rim);
    ++tally_.attempts_by_size[attempt.size];
  }
}

void LeaveEpisodes::end_attempts(const NeighbourLists& neighbours,
                                 std::span<const AgentState> state) {
  const auto ended = [&](const OpenAttempt& attempt) {
    if (state[attempt.agent] == AgentState::Leave) return false;
    if (escaped(attempt, neighbours, state)) {
      tally_.escapes.count(attempt.rim);
      ++tally_.escapes_by_size[attempt.size];
    }
    dead_former_ += attempt.count;
    return true;
  };
  open_.erase(std::remove_if(open_.begin(), open_.end(), ended), open_.end());
  // Amortised: each remembered member is copied at most once per time it is remembered.
  if (dead_former_ > former_.size() / 2) compact_former();
}

bool LeaveEpisodes::escaped(const OpenAttempt& attempt, const NeighbourLists& neighbours,
                            std::span<const AgentState> state) const {
  const auto former_begin = former_.begin() + attempt.first;
  const auto former_end = former_begin + attempt.count;
  for (const Neighbour& nb : neighbours.of(attempt.agent)) {
    if (nb.distance > detection_radius_) break;  // nearest first
    if (state[nb.id] == AgentState::Wait && std::binary_search(former_begin, former_end, nb.id))
      return false;
  }
  return true;
}

// In place: open attempts keep the order they started in, so their ranges lie in
// increasing order and each moves down, never onto a range still to be moved.
void LeaveEpisodes::compact_former() {
  std::size_t end = 0;
  for (OpenAttempt& attempt : open_) {
    const auto begin = former_.begin() + attempt.first;
    std::copy(begin, begin + attempt.count, former_.begin() + static_cast<std::ptrdiff_t>(end));
    attempt.first = static_cast<std::uint32_t>(end);
    end += attempt.count;
  }
  former_.resize(end);
  dead_former_ = 0;
}

}  // namespace swarmagg
