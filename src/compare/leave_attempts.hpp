#pragma once
// Watches one replicate for LEAVE attempts (an agent going WAIT -> LEAVE) and decides for
// each whether the agent left from the rim of its aggregate or from inside it, and whether
// it got out.
//
// Rim: fewer than `rim_below` members of its own aggregate within s just before it left.
// The default k = 5 comes from hexagonal packing at any spacing between 2r and s: an edge
// disc has 4 such neighbours, a corner disc 3, an interior disc 6, and an interior disc
// next to one vacancy still 5 with no gap to leave through. (Aggregates here form at
// spacing about s, where the second shell lies at sqrt(3) s > s, so only the first shell
// counts.)
// Got out: when its LEAVE timeout ends, it perceives (within s) no member of its former
// aggregate that is still waiting; otherwise it stays, or is about to rejoin.
// Attempts still under way when the replicate ends are dropped.
#include <cstdint>
#include <vector>

#include "core/agent_state.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "run/replicate_observer.hpp"

namespace swarmagg {

constexpr int kDefaultRimBelow = 5;

struct LeaveAttempt {
  std::int64_t step = 0;  // the step during which the agent turned to LEAVE
  AgentId agent = 0;
  int members_near = 0;  // members of its aggregate within s just before
  bool rim = false;
  bool got_out = false;
};

// Members of `agent`'s aggregate (aggregate_of) that it perceives within `s`.
int members_within(AgentId agent, const NeighbourLists& neighbours,
                   std::span<const std::int32_t> aggregate_of, double s);

class LeaveAttemptObserver : public ReplicateObserver {
 public:
  // At finish(), the completed attempts are moved into *sink.
  LeaveAttemptObserver(int rim_below, std::vector<LeaveAttempt>* sink)
      : rim_below_(rim_below), sink_(sink) {}
  void observe(const Replicate& replicate) override;
  void finish() override;

 private:
  struct Open {
    LeaveAttempt attempt;
    std::vector<AgentId> former;  // the other members of its aggregate when it left
    bool active = false;
  };
  void open_attempt(const Replicate& replicate, AgentId agent);
  void close_attempt(const Replicate& replicate, AgentId agent);
  void remember(const Replicate& replicate);

  int rim_below_;
  std::vector<LeaveAttempt>* sink_;
  std::vector<LeaveAttempt> done_;
  std::vector<Open> open_;
  // The state of the previous observation: what the controller saw when it decided.
  std::vector<AgentState> previous_state_;
  std::vector<std::int32_t> previous_aggregate_;
  std::vector<int> previous_members_near_;
};

}  // namespace swarmagg
