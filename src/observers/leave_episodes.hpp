#pragma once
// Follows every LEAVE episode of one replicate and tallies them (observers/leave_tally.hpp).
//
// An attempt starts when an agent in an aggregate of size m goes WAIT -> LEAVE. Then it
// records m, the other members of that aggregate, and whether the agent stood on its rim
// (the rim rule of docs/models.md, observers/aggregate_geometry.hpp). The attempt ends when the
// agent stops leaving (its timeout, LEAVE -> GO); it is an escape when at that moment the agent
// perceives (within s) no member of the aggregate it left that is still waiting. A waiting
// agent alone (isolated_wait: stay) has no aggregate to leave: no attempt.
//
// observe_decision() runs once per step, between the controller's decision and the engine's
// move, so the rim and the escape are judged on exactly what the controller saw when it
// decided. It also counts that step's aggregates by size (the exposure). Its cost is linear
// in the agents in aggregates plus the open attempts and the members they remember. It
// allocates nothing per step: room for N remembered members is reserved up front, and only
// worlds whose open attempts remember more (many leavers of large aggregates at once) grow
// it, to a high-water mark.
#include <cstdint>
#include <span>
#include <vector>

#include "control_interface/neighbour_lists.hpp"
#include "core/agent_state.hpp"
#include "observers/aggregate_geometry.hpp"
#include "observers/aggregate_tracker.hpp"
#include "observers/leave_tally.hpp"

namespace swarmagg {

class LeaveEpisodes {
 public:
  LeaveEpisodes(int agent_count, double detection_radius, const ShapeRules& rules);

  // `aggregates`, `neighbours` and `positions`: what the decision started from; `state`:
  // every agent's state after it.
  void observe_decision(const AggregateTracker& aggregates, const NeighbourLists& neighbours,
                        std::span<const Vec2> positions, std::span<const AgentState> state);

  const LeaveTally& tally() const { return tally_; }
  std::size_t open_attempts() const { return open_.size(); }

 private:
  struct OpenAttempt {
    AgentId agent = 0;
    std::int32_t size = 0;  // of the aggregate it left
    bool rim = false;
    std::uint32_t first = 0;  // its former fellow members: former_[first, first + count)
    std::uint32_t count = 0;
  };
  void start_attempts(const AggregateTracker& aggregates, std::span<const Vec2> positions,
                      std::span<const AgentState> state);
  void end_attempts(const NeighbourLists& neighbours, std::span<const AgentState> state);
  bool escaped(const OpenAttempt& attempt, const NeighbourLists& neighbours,
               std::span<const AgentState> state) const;
  void compact_former();

  double detection_radius_;
  ShapeRules rules_;
  LeaveTally tally_;
  std::vector<AgentId> members_;  // of the aggregate an attempt leaves
  std::vector<OpenAttempt> open_;
  std::vector<AgentId> former_;  // sorted ranges, one per open attempt (and dead ones)
  std::size_t dead_former_ = 0;  // entries of former_ that belong to ended attempts
};

}  // namespace swarmagg
