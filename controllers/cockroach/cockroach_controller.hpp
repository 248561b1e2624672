#pragma once
// A neighbour-count aggregation controller, after the cockroach experiments and models of
// Jeanson et al. (2005) and Garnier et al. (2005, 2008): whether an agent stops or leaves
// depends only on how many waiting agents it perceives, not on an aggregate it cannot see.
//  - A GO agent that perceives n >= 1 waiting agents within s stops (WAIT, a growth) with
//    probability stop_probability[n] per step; if it does not stop it heads away from them.
//  - Searchers that perceive no waiting agent pair up as Bayindir's do (nearest first, pairs
//    are mutual; a creation), so aggregates can start.
//  - A WAIT agent that perceives n waiting agents (n >= 0) leaves with probability
//    leave_probability[n] per step.
//  - LEAVE as for every controller: away from the agents it perceives for leave_timeout,
//    then GO (docs/controllers.md).
//  - With compaction (docs/controllers.md), agents that go on waiting close up under the
//    spring force of the waiting members of their aggregate they perceive, solid to every body.
// The last entry of each list holds for larger n. All agents decide at once from the states
// of the previous step, so the result never depends on agent order.
#include <cstdint>
#include <vector>

#include "controllers/compaction.hpp"
#include "controllers/controller.hpp"

namespace swarmagg {

struct CockroachParameters {
  std::vector<double> stop_probability;   // by n = 1, 2, ... waiting agents perceived
  std::vector<double> leave_probability;  // by n = 0, 1, 2, ... waiting agents perceived
  double leave_timeout = 10.0;            // tu
  double speed = 1.0;
  double dt = 0.1;
  double detection_radius = 4.0;
  CompactionRule compaction;
};

class CockroachController final : public Controller {
 public:
  explicit CockroachController(CockroachParameters parameters)
      : parameters_(std::move(parameters)) {}

  void decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& rng,
              std::span<MotionCommand> commands, EventCounts& events) override;

  // The probability an entry of `list` gives for n (the last entry for larger n).
  static double entry(const std::vector<double>& list, std::size_t n);

 private:
  struct SearchPair {
    double distance;
    std::uint32_t a;
    std::uint32_t b;
  };

  int waiting_perceived(std::uint32_t agent, const ControllerInput& input) const;
  int joined_size(std::uint32_t agent, const ControllerInput& input) const;
  void leave(std::uint32_t agent, const ControllerInput& input, SwarmState& swarm,
             const CounterRng& rng);
  void pair_searchers(SwarmState& swarm, EventCounts& events);
  void write_commands(const SwarmState& swarm, std::span<MotionCommand> commands) const;
  void compact(const ControllerInput& input, const SwarmState& swarm,
               std::span<MotionCommand> commands) const;

  CockroachParameters parameters_;
  std::vector<AgentState> previous_;
  std::vector<std::int32_t> leavers_left_;  // per aggregate: members not yet counted leaving
  std::vector<SearchPair> pairs_;
  std::vector<std::uint8_t> stopped_;  // searchers that stopped during this decision
};

}  // namespace swarmagg
