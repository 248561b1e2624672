#include "compare/leave_attempts.hpp"

#include "run/replicate.hpp"

namespace swarmagg {

int members_within(AgentId agent, const NeighbourLists& neighbours,
                   std::span<const std::int32_t> aggregate_of, double s) {
  const std::int32_t own = aggregate_of[agent];
  if (own < 0) return 0;
  int count = 0;
  for (const Neighbour& nb : neighbours.of(agent)) {
    if (nb.distance > s) break;  // nearest first
    if (aggregate_of[nb.id] == own) ++count;
  }
  return count;
}

void LeaveAttemptObserver::observe(const Replicate& replicate) {
  const std::span<const AgentState> state = replicate.swarm().state;
  if (!previous_state_.empty()) {
    for (AgentId i = 0; i < state.size(); ++i) {
      if (previous_state_[i] == AgentState::Wait && state[i] == AgentState::Leave) {
        open_attempt(replicate, i);
      } else if (previous_state_[i] == AgentState::Leave && state[i] != AgentState::Leave) {
        close_attempt(replicate, i);
      }
    }
  }
  remember(replicate);
}

void LeaveAttemptObserver::open_attempt(const Replicate& replicate, AgentId agent) {
  // A lone waiting agent (isolated_wait: stay) has no aggregate to get out of.
  const std::int32_t own = previous_aggregate_[agent];
  if (own < 0) return;
  Open& open = open_[agent];
  open.active = true;
  open.attempt = LeaveAttempt{replicate.steps_done() - 1, agent, previous_members_near_[agent],
                              previous_members_near_[agent] < rim_below_, false};
  open.former.clear();
  for (AgentId j = 0; j < previous_aggregate_.size(); ++j) {
    if (j != agent && previous_aggregate_[j] == own) open.former.push_back(j);
  }
}

void LeaveAttemptObserver::close_attempt(const Replicate& replicate, AgentId agent) {
  Open& open = open_[agent];
  if (!open.active) return;
  open.active = false;
  const double s = replicate.spec().robots.detection_radius;
  const std::span<const AgentState> state = replicate.swarm().state;
  bool near_former = false;
  for (const Neighbour& nb : replicate.engine().neighbours().of(agent)) {
    if (nb.distance > s) break;
    if (state[nb.id] != AgentState::Wait) continue;
    for (AgentId f : open.former) near_former = near_former || f == nb.id;
  }
  open.attempt.got_out = !near_former;
  done_.push_back(open.attempt);
}

void LeaveAttemptObserver::remember(const Replicate& replicate) {
  const std::span<const AgentState> state = replicate.swarm().state;
  const std::span<const std::int32_t> aggregate_of = replicate.aggregates().aggregate_of();
  const NeighbourLists& neighbours = replicate.engine().neighbours();
  const double s = replicate.spec().robots.detection_radius;
  previous_state_.assign(state.begin(), state.end());
  previous_aggregate_.assign(aggregate_of.begin(), aggregate_of.end());
  previous_members_near_.resize(state.size());
  open_.resize(state.size());
  for (AgentId i = 0; i < state.size(); ++i) {
    previous_members_near_[i] =
        state[i] == AgentState::Wait ? members_within(i, neighbours, aggregate_of, s) : 0;
  }
}

void LeaveAttemptObserver::finish() {
  *sink_ = std::move(done_);
}

}  // namespace swarmagg
