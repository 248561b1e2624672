#pragma once
// Follows every LEAVE episode of one replicate and tallies them (observers/leave_tally.hpp).
//
// An attempt starts when an agent in an aggregate of size m goes WAIT -> LEAVE. Then it
// records m, the other members of that aggregate, and whether the agent stood on its rim
// (the rim rule of docs/models.md, observers/aggregate_geometry.hpp). The LEAVE phase ends
// when the agent stops leaving (its timeout, LEAVE -> GO); the attempt is an escape when at that
// moment the agent perceives, within the escape radius, no member of the aggregate it left that is
// still waiting (has waited without a break since the attempt started). The escape radius is the
// distance at which the controller would steer back: the approach radius for a controller that
// approaches (Soysal), else the detection radius. A waiting agent alone (isolated_wait: stay) has
// no aggregate to leave: no attempt.
//
// After its LEAVE phase the attempt stays open as an excursion until the agent is next seen
// in an aggregate, or until the return window has passed. It is a return when that aggregate
// holds a member of the one it left that kept waiting all the while (alone, too, under
// isolated_wait: stay), and the agent joined it within the window (measured from the start of
// the attempt). A former member who searched again in between (its pair fell apart) and then
// waits beside the agent is in a new aggregate, a creation or a join of another one. The fraction
// that returned counts only attempts whose window closed within the run: at its end, one still away
// could yet have come back (a run of 200 tu cut 15 % of its attempts short, and counted them as not
// returning). A return remembers how long it took, the size of the aggregate it joined, and the
// searcher exposure it spent away (the aggregates of each size that existed at each decision of the
// excursion), which a rate of new joins must leave out.
//
// observe_decision() runs once per step, between the controller's decision and the engine's
// move, so the rim and the escape are judged on exactly what the controller saw when it
// decided. It also counts that step's aggregates by size (the exposure). Its cost is linear
// in the agents in aggregates plus the open attempts and the members and sizes they remember.
// The attempts that leave one aggregate in one decision share one list of its members: a packed
// aggregate of 4 x 10^4 with a few dozen leavers a step otherwise remembered it a few dozen
// times a step (1.6 GB over 5 tu). It allocates nothing per step for aggregates of fewer than
// 64 members: room for 4N remembered members, N remembered sizes and N member lists is reserved
// up front, and only worlds whose open attempts remember more grow it, to a high-water mark.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "control_interface/neighbour_lists.hpp"
#include "core/agent_state.hpp"
#include "observers/aggregate_geometry.hpp"
#include "observers/aggregate_tracker.hpp"
#include "observers/leave_tally.hpp"

namespace swarmagg {

struct EpisodeRules {
  double escape_radius = 0.0;     // within it a waiting former member holds the leaver
  double detection_radius = 0.0;  // s: a join is filed under the size of the aggregate within it
  // Decisions after the attempt starts within which a return counts (0: none counts).
  std::int64_t return_window_steps = 0;
};

class LeaveEpisodes {
 public:
  LeaveEpisodes(int agent_count, const EpisodeRules& episodes, const ShapeRules& rules);

  // `aggregates`, `neighbours` and `positions`: what the decision started from; `state`:
  // every agent's state after it.
  void observe_decision(const AggregateTracker& aggregates, const NeighbourLists& neighbours,
                        std::span<const Vec2> positions, std::span<const AgentState> state);

  const LeaveTally& tally() const { return tally_; }
  // Attempts not yet decided: leaving, or on an excursion that may still return.
  std::size_t open_attempts() const { return open_.size(); }

 private:
  struct OpenAttempt {
    AgentId agent = 0;
    std::int32_t size = 0;  // of the aggregate it left
    bool rim = false;
    bool leaving = true;            // in its LEAVE phase (else on the excursion after it)
    std::int64_t start = 0;         // the decision it started in
    std::uint32_t former = 0;       // its aggregate's members then: former_sets_[former]
    std::uint32_t sizes_first = 0;  // the aggregate steps by size when it started:
    std::uint32_t sizes = 0;        // sizes_at_start_[sizes_first, sizes_first + sizes)
    std::int32_t joined_size = -1;  // the size its join was filed under, once it waits again
  };
  // The members of an aggregate that attempts left in one decision, the leavers included:
  // former_[first, first + count), sorted; `users` of the open attempts remember it.
  struct FormerSet {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    std::uint32_t users = 0;
  };
  struct Leaver {
    std::int32_t aggregate;
    AgentId agent;
    bool operator<(const Leaver& o) const {
      return aggregate != o.aggregate ? aggregate < o.aggregate : agent < o.agent;
    }
  };
  void start_attempts(const AggregateTracker& aggregates, std::span<const Vec2> positions,
                      std::span<const AgentState> state);
  // True when the attempt is decided (its excursion ended) and may be forgotten.
  bool advance(OpenAttempt& attempt, const AggregateTracker& aggregates,
               const NeighbourLists& neighbours, std::span<const AgentState> state);
  bool escaped(const OpenAttempt& attempt, const NeighbourLists& neighbours,
               std::span<const AgentState> state) const;
  std::int32_t size_joined(AgentId agent, const AggregateTracker& aggregates,
                           const NeighbourLists& neighbours) const;
  bool holds_former_member(const OpenAttempt& attempt, std::int32_t aggregate,
                           const AggregateTracker& aggregates) const;
  std::span<const AgentId> former_members(const OpenAttempt& attempt) const;
  void start_attempt(AgentId agent, std::int32_t size, bool rim);
  void count_return(const OpenAttempt& attempt, std::int32_t joined_size);
  // An attempt decided before its return window closed waits in closing_ until it closes.
  void close_when_due(const OpenAttempt& attempt, bool returned);
  void close(std::int32_t size, bool returned, std::int64_t away);
  void close_due_attempts();
  bool window_closed(std::int64_t start) const {
    return decision_ - 1 - start > episodes_.return_window_steps;
  }
  void compact();

  EpisodeRules episodes_;
  ShapeRules rules_;
  LeaveTally tally_;
  std::int64_t decision_ = 0;
  std::size_t sizes_seen_ = 0;    // 1 + the largest aggregate size counted so far
  std::vector<AgentId> members_;  // of the aggregate an attempt leaves
  std::vector<Leaver> leavers_;   // of the decision at hand
  std::vector<OpenAttempt> open_;
  // Per agent, the decision since which it has waited without a break (kNotWaiting: it does
  // not wait), as the state after each decision says.
  static constexpr std::int64_t kNotWaiting = std::numeric_limits<std::int64_t>::max();
  std::vector<std::int64_t> waiting_since_;
  std::vector<AgentState> state_before_;  // each agent's state after the last decision
  void note_waiting(std::span<const AgentState> state);
  struct Closing {
    std::int64_t start = 0;
    std::int32_t size = 0;
    bool returned = false;
    std::int64_t away = 0;  // steps, for a return
  };
  std::vector<Closing> closing_;
  std::vector<AgentId> former_;  // sorted ranges, one per FormerSet (live or dead)
  std::vector<FormerSet> former_sets_;
  std::vector<std::uint32_t> renumbered_;  // compact()'s: the new index of each former set
  // Snapshots of the aggregate steps by size, one per decision that started attempts (and
  // dead ones), shared by that decision's attempts.
  std::vector<std::int64_t> sizes_at_start_;
  std::uint32_t snapshot_first_ = 0;  // where this decision's snapshot starts
  std::size_t dead_former_ = 0;       // entries of former_ no open attempt remembers
  static constexpr std::size_t kFormerPerAgent = 4;
};

}  // namespace swarmagg
