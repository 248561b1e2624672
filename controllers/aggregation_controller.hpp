#pragma once
// The GO / APPROACH / WAIT / LEAVE state machine (docs/controllers.md). All agents decide at once
// from the states of the previous step, so the result never depends on agent order:
//  - LEAVE agents count down their timeout, then search again (GO, new random heading);
//  - WAIT agents resume GO when isolated (if the rules say so), else leave with P_l(i);
//  - searching agents (GO, APPROACH) within s of a waiting agent join it (if allowed); the
//    rest pair up with the nearest other searching agent (greedy by distance, so pairs are
//    mutual); with joining allowed, a searcher whose neighbour paired joins that pair;
//  - Soysal's searchers head for the nearest non-leaving agent within s_a (APPROACH);
//  - with compaction, agents that go on waiting move under the spring force of the waiting
//    members of their aggregate they perceive (docs/controllers.md), solid to waiting and leaving
//    bodies.
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "controllers/aggregation_rules.hpp"
#include "controllers/controller.hpp"

namespace swarmagg {

class AggregationController final : public Controller {
 public:
  explicit AggregationController(const AggregationRules& rules)
      : rules_(rules),
        standing_norm2_(standing_norm2(rules.compaction.tolerance)),
        leave_counts_neighbours_(rules.leave_rule.law != LeaveLaw::Constant &&
                                 rules.leave_rule.size_source == LeaveSize::Neighbours),
        leave_same_for_all_(rules.leave_rule.law == LeaveLaw::Constant),
        leave_p_for_all_(leave_probability(rules.leave_rule, 1, 0)),
        leave_draws_below_(draws_below(leave_p_for_all_)) {}

  void decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
              std::span<MotionCommand> commands, EventCounts& events) override;

 private:
  // Agent indices, kept at full length so that refilling writes only what is used.
  struct IndexList {
    std::vector<std::uint32_t> slots;
    std::size_t count = 0;
    const std::uint32_t* begin() const { return slots.data(); }
    const std::uint32_t* end() const { return slots.data() + count; }
  };

  struct SearchPair {
    double distance;
    std::uint32_t a;
    std::uint32_t b;
  };

  // What a waiting agent perceives within s, read in one pass over its list.
  struct WaitingView {
    int perceived = 0;          // agents within s
    bool sees_waiting = false;  // one of them waited
    Vec2 force;                 // spring force of the waiting members among them (compaction)
  };

  struct Mover {
    std::uint32_t agent;
    Vec2 force;  // the net spring force on it
  };

  // A decision in which every agent waited and nothing changed. While its inputs stay the
  // same, the next decision differs from it only by the leave draws: when none of them
  // fires, it gives the same commands and changes nothing either.
  struct SteadyDecision {
    bool valid = false;
    const NeighbourLists* lists = nullptr;
    std::uint64_t generation = 0;
    std::vector<std::int32_t> labels;
    std::vector<std::int32_t> sizes;
    std::vector<std::int32_t> partners;
    std::vector<MotionCommand> commands;
  };

  // The probability that a waiting agent in an aggregate of `aggregate_size` that perceives
  // `perceived` agents leaves in one decision (the constant law's is the same for all).
  double leave_chance(std::int32_t aggregate_size, int perceived) const {
    return leave_same_for_all_ ? leave_p_for_all_
                               : leave_probability(rules_.leave_rule, aggregate_size,
                                                   leave_counts_neighbours_ ? perceived : 0);
  }
  // Repeats the steady decision (its commands, nothing changed) when the inputs are those it
  // was made from and no agent draws to leave; false (nothing done) otherwise.
  bool repeat_steady(const ControllerInput& input, const SwarmState& swarm, const CounterRng& rng,
                     std::span<MotionCommand> commands) const;
  void remember_if_steady(const ControllerInput& input, const SwarmState& swarm,
                          std::span<const MotionCommand> commands);

  bool searching(std::uint32_t agent) const;
  bool may_join(std::uint32_t agent) const;  // may a searcher stop for this agent?
  // Compaction: the movers' velocities (update_waiting found their forces), after the joins.
  void close_up(const ControllerInput& input, std::span<MotionCommand> commands) const;
  // Whether a searcher joined in this decision within s of `agent`.
  bool joined_beside(std::uint32_t agent, const ControllerInput& input) const;

  void update_leaving(std::uint32_t agent, const ControllerInput& input, SwarmState& swarm,
                      const CounterRng& rng);
  bool views_stand_for(const ControllerInput& input, const SwarmState& swarm);
  void update_waiting(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
                      EventCounts& events);
  template <bool kJoin, bool kCompaction>
  void update_waiting_as(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
                         EventCounts& events);
  void join_waiting(const ControllerInput& input, SwarmState& swarm, EventCounts& events);
  void pair_searchers(const ControllerInput& input, SwarmState& swarm, EventCounts& events);
  void steer_searchers(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng);
  std::optional<Vec2> escape_direction(std::uint32_t agent, const ControllerInput& input) const;
  void write_commands(const SwarmState& swarm, std::span<MotionCommand> commands) const;
  void list_by_state(std::size_t n);

  AggregationRules rules_;
  double standing_norm2_;         // compaction: squared net forces below it stand (standing_norm2)
  bool leave_counts_neighbours_;  // the leave law's size is the perceived agents + 1
  bool leave_same_for_all_;
  double leave_p_for_all_;
  // The constant law by whole draws: uniform() < p exactly when the draw's 53 bits are below
  // this (uniform() is those bits times 2^-53, and p times 2^53 is exact).
  std::uint64_t leave_draws_below_;
  static std::uint64_t draws_below(double p) {
    return p <= 0.0   ? 0
           : p >= 1.0 ? std::uint64_t{1} << 53
                      : static_cast<std::uint64_t>(std::ceil(std::ldexp(p, 53)));
  }
  SteadyDecision steady_;
  std::vector<AgentState> previous_;
  std::vector<std::uint8_t> settled_;  // searchers that stopped in this decision (kJoined, kPaired)
  std::vector<SearchPair> pairs_;
  std::vector<std::int32_t> leavers_left_;  // per aggregate: members not yet counted leaving
  // Waiting agents that go on waiting under a net spring force that may move them
  // (compaction); the rest stand. Kept at full length, like IndexList.
  std::vector<Mover> movers_;
  std::size_t mover_count_ = 0;
  // The waiting agents' views, by agent, and what they were computed from.
  std::vector<WaitingView> views_;
  const NeighbourLists* views_lists_ = nullptr;
  std::uint64_t views_generation_ = 0;
  std::vector<AgentState> views_states_;
  std::vector<std::int32_t> views_labels_;
  std::vector<std::int32_t> views_partners_;
  const NeighbourLists* seen_lists_ = nullptr;  // the lists of the last decision
  std::uint64_t seen_generation_ = 0;
  // Agents by the state they start the decision in (index order).
  IndexList searchers_;
  IndexList waiters_;
  IndexList leavers_;
};

}  // namespace swarmagg
