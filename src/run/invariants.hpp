#pragma once
// Invariants a replicate must keep after every step. Checked in Debug builds and under
// `--check`; a violation stops the run with an InvariantViolation naming the replicate, the
// step, the agent and the values. Every check is O(N + neighbour pairs), like a step.
//
// After each step:
//  - the engine, the controller state and the aggregate tracker all hold N agents;
//  - positions are finite and inside the arena (with walls, the centre at least r from each
//    wall, up to the engine's tolerance); headings, hence commanded velocities, are finite
//    unit vectors; states are valid and allowed by the rules (APPROACH only for Soysal, no
//    LEAVE when leaving is off, only GO for ghost collisions); leave timers lie in
//    [0, leave_timeout];
//  - aggregates are the connected components of WAIT agents: each has >= 2 members (exactly
//    2 with partner links), its size is the number of agents labelled with it, only WAIT
//    agents are labelled, linked WAIT agents share one, `largest` is the largest size; so
//    NOA <= waiting / 2;
//  - the cumulative events account for the waiting agents: an agent enters WAIT only by a
//    creation (two agents) or a growth (one), and each counted dissipation or shrink takes
//    one out, so 2 creations + growths - dissipations - shrinks >= waiting; the rules
//    switch events off (no growth without joining, no dissipation or shrink without
//    leaving, no shrink with partner links, no event at all for ghost collisions).
//  - sleep (kinematic engine): the step resolved in full moves no agent that slept and
//    changes nothing the sleeping step gave (the engine runs both while checks are on);
// From one step to the next:
//  - cumulative event counts never decrease;
//  - kinematic engine (exact): no agent moves farther than v dt, waiting agents stay put;
//  - two bodies solid to each other during the step (a WAIT agent and a LEAVE agent, or a
//    searching one when joining is allowed: docs/architecture.md) do not sink into each other:
//    their overlap grows by at most the engine's tolerance (rounding for the kinematic engine; r
//    for Box2D, which lets bodies overlap by a substep's travel before it resolves a contact).
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/controller_rules.hpp"
#include "control_interface/event_counts.hpp"
#include "control_interface/motion_command.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "core/agent_state.hpp"
#include "core/vec2.hpp"
#include "observers/aggregate_tracker.hpp"

namespace swarmagg {

class Replicate;

class InvariantViolation : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the checks read of a replicate after a step.
struct CheckedState {
  const WorldSpec& spec;
  const ControllerRules& rules;  // what the world's controller allows
  int replicate = 0;
  std::int64_t step = 0;
  std::span<const Vec2> positions;
  const NeighbourLists& neighbours;
  const SwarmState& swarm;  // states as displayed during the step just done
  const AggregateTracker& aggregates;
  const EventCounts& events;
  std::optional<std::uint32_t> sleeper_due_to_move;  // the engine's sleep check
  // The step's commands and the signals agents displayed: their blocked_by masks say which
  // pairs were solid (docs/controllers.md: the masks are the whole contract).
  std::span<const MotionCommand> commands = {};
  std::span<const Signal> signals = {};
};

CheckedState checked_state(const Replicate& replicate);

class InvariantChecker {
 public:
  // Checks one step; the step-to-step invariants too when the previous call checked the
  // same world's same replicate one step earlier.
  void check(const CheckedState& state);
  // The next check starts a new history.
  void forget() { step_ = -1; }

 private:
  bool continues(const CheckedState& state) const;
  void check_counts_grow(const CheckedState& state) const;
  void check_motion(const CheckedState& state) const;
  void check_contacts(const CheckedState& state) const;
  void check_aggregates(const CheckedState& state);
  void remember(const CheckedState& state);

  const WorldSpec* spec_ = nullptr;
  int replicate_ = -1;
  std::int64_t step_ = -1;
  std::vector<Vec2> positions_;
  EventCounts events_;
  std::vector<std::int32_t> members_;  // scratch: agents labelled with each aggregate
};

// Replicate's hook: checks with a per-thread checker that follows the replicate it last
// checked (a replicate runs on one thread), so Replicate needs to hold no checker state.
void check_invariants(const Replicate& replicate);

}  // namespace swarmagg
