#include "observers/leave_episodes.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#include "control_interface/joined_size.hpp"

namespace swarmagg {

LeaveEpisodes::LeaveEpisodes(int agent_count, const EpisodeRules& episodes, const ShapeRules& rules)
    : episodes_(episodes), rules_(rules) {
  tally_.resize(agent_count);
  const auto agents = static_cast<std::size_t>(agent_count);
  open_.reserve(agents);  // one attempt per agent at most
  closing_.reserve(agents);
  waiting_since_.assign(agents, kNotWaiting);
  // No agent waits before the first decision: the first that waits is noted then.
  state_before_.assign(agents, AgentState::Go);
  // Room for several remembered members per agent (attempts stay open through their
  // excursion, up to the return window) and for as many remembered sizes as there are
  // agents (one snapshot per decision that starts attempts), so that most runs never grow
  // them.
  former_.reserve(kFormerPerAgent * agents);
  former_sets_.reserve(agents);  // live ones: one per open attempt at most
  renumbered_.reserve(agents);
  leavers_.reserve(agents);
  sizes_at_start_.reserve(agents);
  members_.reserve(agents);  // the largest aggregate's bound
}

void LeaveEpisodes::observe_decision(const AggregateTracker& aggregates,
                                     const NeighbourLists& neighbours,
                                     std::span<const Vec2> positions,
                                     std::span<const AgentState> state) {
  ++decision_;
  // Attempts are advanced before this decision's aggregates are counted: a return's time
  // away ends with the decision in which it went WAIT, the one before.
  std::size_t kept = 0;
  for (OpenAttempt& attempt : open_) {
    if (advance(attempt, aggregates, neighbours, state)) {
      FormerSet& former = former_sets_[attempt.former];
      if (--former.users == 0) dead_former_ += former.count;
    } else {
      open_[kept++] = attempt;
    }
  }
  open_.resize(kept);
  close_due_attempts();
  // Amortised: each remembered entry is copied at most once per time it is remembered. The
  // snapshots are compacted before they would outgrow their room.
  if (dead_former_ > former_.size() / 2 ||
      sizes_at_start_.size() + 2 * sizes_seen_ + 2 > sizes_at_start_.capacity())
    compact();
  for (const std::int32_t size : aggregates.sizes()) {
    ++tally_.aggregate_steps_by_size[size];
    sizes_seen_ = std::max(sizes_seen_, static_cast<std::size_t>(size) + 1);
  }
  start_attempts(aggregates, positions, state);
  note_waiting(state);
}

// After the attempts were advanced on the states before this decision. Few agents change
// state in a decision: blocks of states equal to the last decision's are passed over whole,
// so a world that does not wait (ghost) or rests costs a compare of its states.
void LeaveEpisodes::note_waiting(std::span<const AgentState> state) {
  constexpr std::size_t kBlock = 64;
  const std::size_t n = state.size();
  for (std::size_t first = 0; first < n; first += kBlock) {
    const std::size_t count = std::min(kBlock, n - first);
    if (std::memcmp(state.data() + first, state_before_.data() + first,
                    count * sizeof(AgentState)) == 0)
      continue;
    for (std::size_t i = first; i < first + count; ++i) {
      if (state[i] == state_before_[i]) continue;
      const bool was_waiting = state_before_[i] == AgentState::Wait;
      const bool waits = state[i] == AgentState::Wait;
      if (waits != was_waiting) waiting_since_[i] = waits ? decision_ : kNotWaiting;
      state_before_[i] = state[i];
    }
  }
}

// Every agent in an aggregate was waiting when the decision started, so one now leaving has
// just gone WAIT -> LEAVE. The leavers of one aggregate are taken together: its members are
// listed (and its rim found) once for all of them.
void LeaveEpisodes::start_attempts(const AggregateTracker& aggregates,
                                   std::span<const Vec2> positions,
                                   std::span<const AgentState> state) {
  leavers_.clear();
  for (const AgentId i : aggregates.aggregated_agents()) {
    if (state[i] == AgentState::Leave) leavers_.push_back({aggregates.aggregate_of()[i], i});
  }
  if (leavers_.empty()) return;
  // One snapshot of the aggregate steps by size serves every attempt of this decision.
  snapshot_first_ = static_cast<std::uint32_t>(sizes_at_start_.size());
  const auto steps = tally_.aggregate_steps_by_size.begin();
  sizes_at_start_.insert(sizes_at_start_.end(), steps,
                         steps + static_cast<std::ptrdiff_t>(sizes_seen_));
  std::sort(leavers_.begin(), leavers_.end());
  for (std::size_t k = 0; k < leavers_.size();) {
    const std::int32_t aggregate = leavers_[k].aggregate;
    aggregates.members_of(leavers_[k].agent, members_);
    former_sets_.push_back({static_cast<std::uint32_t>(former_.size()),
                            static_cast<std::uint32_t>(members_.size()), 0});
    former_.insert(former_.end(), members_.begin(), members_.end());
    const RimCounter rim(members_, positions, rules_);
    const std::int32_t size = aggregates.sizes()[static_cast<std::size_t>(aggregate)];
    for (; k < leavers_.size() && leavers_[k].aggregate == aggregate; ++k) {
      start_attempt(leavers_[k].agent, size, rim.on_rim(leavers_[k].agent));
    }
  }
}

void LeaveEpisodes::start_attempt(AgentId agent, std::int32_t size, bool rim) {
  OpenAttempt attempt;
  attempt.agent = agent;
  attempt.size = size;
  attempt.rim = rim;
  attempt.start = decision_;
  attempt.former = static_cast<std::uint32_t>(former_sets_.size() - 1);
  ++former_sets_.back().users;
  attempt.sizes_first = snapshot_first_;
  attempt.sizes = static_cast<std::uint32_t>(sizes_seen_);
  open_.push_back(attempt);
  tally_.attempts.count(rim);
  ++tally_.attempts_by_size[size];
}

bool LeaveEpisodes::advance(OpenAttempt& attempt, const AggregateTracker& aggregates,
                            const NeighbourLists& neighbours, std::span<const AgentState> state) {
  if (attempt.leaving) {
    if (state[attempt.agent] == AgentState::Leave) return false;
    if (escaped(attempt, neighbours, state)) {
      tally_.escapes.count(attempt.rim);
      ++tally_.escapes_by_size[attempt.size];
    }
    attempt.leaving = false;
    if (episodes_.return_window_steps > 0) return false;
    close(attempt.size, false, 0);  // no return counts
    return true;
  }
  // It went WAIT in the decision before the one that first sees it in an aggregate.
  const std::int32_t aggregate = aggregates.aggregate_of()[attempt.agent];
  const bool in_time = decision_ - 1 - attempt.start <= episodes_.return_window_steps;
  if (aggregate >= 0) {
    // A return joins a former member that kept waiting. Pairing again with one who searched
    // again (its pair fell apart) makes a new aggregate, which the models count as a creation;
    // counted as a return too, the measured model kept the pair and created it again.
    const bool returned = in_time && holds_former_member(attempt, aggregate, aggregates);
    if (returned) {
      count_return(attempt, attempt.joined_size >= 0
                                ? attempt.joined_size
                                : aggregates.sizes()[static_cast<std::size_t>(aggregate)] - 1);
    }
    close_when_due(attempt, returned);
    return true;
  }
  if (state[attempt.agent] != AgentState::Wait) {
    attempt.joined_size = -1;
  } else if (attempt.joined_size < 0) {
    attempt.joined_size = size_joined(attempt.agent, aggregates, neighbours);
  }
  if (in_time) return false;
  close(attempt.size, false, 0);
  return true;
}

// The size a join decided now is filed under, as the controllers file growths
// (control_interface/joined_size.hpp). The tracker, a step later, sees the size after every join of
// that decision, so a return filed by it fell under another size than its growth when several
// agents joined at once.
std::int32_t LeaveEpisodes::size_joined(AgentId agent, const AggregateTracker& aggregates,
                                        const NeighbourLists& neighbours) const {
  return joined_aggregate_size(neighbours.of(agent), episodes_.detection_radius, state_before_,
                               aggregates.size_of_agent());
}

void LeaveEpisodes::close_when_due(const OpenAttempt& attempt, bool returned) {
  const std::int64_t away = decision_ - 1 - attempt.start;
  if (window_closed(attempt.start)) {
    close(attempt.size, returned, away);
  } else {
    closing_.push_back({attempt.start, attempt.size, returned, away});
  }
}

void LeaveEpisodes::close(std::int32_t size, bool returned, std::int64_t away) {
  const auto m = static_cast<std::size_t>(size);
  ++tally_.return_attempts_by_size[m];
  if (!returned) return;
  ++tally_.returns_by_size[m];
  tally_.return_steps_by_size[m] += away;
  tally_.return_square_steps_by_size[m] += away * away;
}

void LeaveEpisodes::close_due_attempts() {
  std::size_t kept = 0;
  for (const Closing& c : closing_) {
    if (window_closed(c.start)) {
      close(c.size, c.returned, c.away);
    } else {
      closing_[kept++] = c;
    }
  }
  closing_.resize(kept);
}

// The aggregate's members when the attempt started, the agent itself among them (which no
// neighbour list holds, and holds_former_member passes over).
std::span<const AgentId> LeaveEpisodes::former_members(const OpenAttempt& attempt) const {
  const FormerSet& set = former_sets_[attempt.former];
  return {former_.data() + set.first, set.count};
}

// Held by a former member that is still waiting: one that has waited without a break since
// the attempt started (as a return needs). One that searched in between (its pair fell apart)
// and waits again, in another aggregate, holds nobody: counted, the pairs of a world that
// resumes searching escaped 49 times in 60 attempts where almost none can be held.
bool LeaveEpisodes::escaped(const OpenAttempt& attempt, const NeighbourLists& neighbours,
                            std::span<const AgentState> state) const {
  const std::span<const AgentId> former = former_members(attempt);
  for (const Neighbour& nb : neighbours.of(attempt.agent)) {
    if (nb.distance > episodes_.escape_radius) break;  // nearest first
    const bool kept_waiting =
        state[nb.id] == AgentState::Wait && waiting_since_[nb.id] <= attempt.start;
    if (kept_waiting && std::binary_search(former.begin(), former.end(), nb.id)) return false;
  }
  return true;
}

bool LeaveEpisodes::holds_former_member(const OpenAttempt& attempt, std::int32_t aggregate,
                                        const AggregateTracker& aggregates) const {
  return std::ranges::any_of(former_members(attempt), [&](AgentId j) {
    return j != attempt.agent && aggregates.aggregate_of()[j] == aggregate &&
           waiting_since_[j] <= attempt.start;
  });
}

// The exposure spent away: the aggregate steps by size counted since the attempt started
// (sizes that had never existed then were at 0).
void LeaveEpisodes::count_return(const OpenAttempt& attempt, std::int32_t joined_size) {
  ++tally_.returns_into_size[static_cast<std::size_t>(joined_size)];
  for (std::size_t k = 0; k < sizes_seen_; ++k) {
    const std::int64_t before = k < attempt.sizes ? sizes_at_start_[attempt.sizes_first + k] : 0;
    tally_.returning_aggregate_steps_by_size[k] += tally_.aggregate_steps_by_size[k] - before;
  }
}

// In place: former sets and snapshots lie in the order they were made, so each live one moves
// down, never onto one still to be moved. Open attempts keep the order they started in, so the
// attempts of one decision, which share a snapshot, are neighbours: it moves once, for the
// first of them.
void LeaveEpisodes::compact() {
  std::size_t former_end = 0;
  renumbered_.resize(former_sets_.size());
  std::uint32_t kept = 0;
  for (std::size_t s = 0; s < former_sets_.size(); ++s) {
    FormerSet set = former_sets_[s];
    if (set.users == 0) continue;
    std::copy(former_.begin() + set.first, former_.begin() + set.first + set.count,
              former_.begin() + static_cast<std::ptrdiff_t>(former_end));
    set.first = static_cast<std::uint32_t>(former_end);
    former_end += set.count;
    former_sets_[kept] = set;
    renumbered_[s] = kept++;
  }
  former_sets_.resize(kept);
  former_.resize(former_end);
  dead_former_ = 0;
  std::size_t sizes_end = 0;
  std::uint32_t moved_from = std::numeric_limits<std::uint32_t>::max(), moved_to = 0;
  for (OpenAttempt& attempt : open_) {
    attempt.former = renumbered_[attempt.former];
    if (attempt.sizes_first != moved_from) {
      moved_from = attempt.sizes_first;
      moved_to = static_cast<std::uint32_t>(sizes_end);
      const auto sizes = sizes_at_start_.begin() + attempt.sizes_first;
      std::copy(sizes, sizes + attempt.sizes,
                sizes_at_start_.begin() + static_cast<std::ptrdiff_t>(sizes_end));
      sizes_end += attempt.sizes;
    }
    attempt.sizes_first = moved_to;
  }
  sizes_at_start_.resize(sizes_end);
}

}  // namespace swarmagg
