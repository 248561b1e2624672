#pragma once
// The replicate loop (run/replicate.cpp) with one agent sent to LEAVE by hand once its
// aggregate has formed, for the tests that ask whether leaving is peripheral: on the engine
// the world names, with the controller the world names, every step as a run takes it.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "control_interface/state_signals.hpp"
#include "controllers/controller.hpp"
#include "core/agent_state.hpp"
#include "core/rng.hpp"
#include "core/vec2.hpp"
#include "engine/engine.hpp"
#include "observers/aggregate_tracker.hpp"

namespace swarmagg::testing {

inline bool perceives_waiting(const NeighbourLists& neighbours, const SwarmState& swarm,
                              AgentId agent, double s) {
  for (const Neighbour& n : neighbours.of(agent)) {
    if (n.distance <= s && swarm.state[n.id] == AgentState::Wait) return true;
  }
  return false;
}

// Runs `spec` from `start`, sends `leaver` to LEAVE at step `leave_at` (every agent must be
// waiting by then) and returns whether it still perceived a waiting agent when its timeout ran
// out, in the decision that ends it: then it joins again and did not get out (docs/models.md).
// `after_step` sees the engine after every step taken before that decision. A LEAVE state
// that never ends within 400 steps fails the test and counts as not out.
inline bool caught_at_timeout(const WorldSpec& spec, const std::vector<Vec2>& start, AgentId leaver,
                              std::uint64_t seed, std::int64_t leave_at,
                              const std::function<void(const Engine&)>& after_step = {}) {
  auto engine = make_engine(spec, start);
  auto controller = make_controller(spec);
  SwarmState swarm;
  swarm.resize(start.size());
  AggregateTracker aggregates;
  EventCounts events;
  const CounterRng rng = CounterRng::for_replicate(seed, 0);
  std::vector<MotionCommand> commands(start.size());
  std::vector<Signal> signals(start.size());
  const double s = spec.robots.detection_radius;
  for (std::int64_t step = 0; step < 400; ++step) {
    aggregates.update(engine->neighbours(), swarm, s, AggregateLinks::Proximity);
    if (step == leave_at) {
      for (const AgentState state : swarm.state) EXPECT_EQ(state, AgentState::Wait);
      swarm.state[leaver] = AgentState::Leave;
      swarm.leave_time_left[leaver] = spec.controller.leave_timeout;
    }
    const AgentState before = swarm.state[leaver];
    const ControllerInput input{step, engine->neighbours(), engine->reflections(),
                                aggregates.facts()};
    controller->decide(input, swarm, rng, commands, events);
    if (before == AgentState::Leave && swarm.state[leaver] == AgentState::Go) {
      return perceives_waiting(engine->neighbours(), swarm, leaver, s);
    }
    write_signals(swarm.state, signals);
    engine->step(commands, signals);
    if (after_step) after_step(*engine);
  }
  ADD_FAILURE() << "the LEAVE state never ended";
  return true;
}

}  // namespace swarmagg::testing
