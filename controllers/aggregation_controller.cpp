#include "controllers/aggregation_controller.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace swarmagg {

bool AggregationController::searching(std::uint32_t agent) const {
  return previous_[agent] == AgentState::Go || previous_[agent] == AgentState::Approach;
}

bool AggregationController::may_join(std::uint32_t agent) const {
  return searching(agent) || (rules_.join && previous_[agent] == AgentState::Wait);
}

int AggregationController::perceived_within_s(std::uint32_t agent,
                                              const ControllerInput& input) const {
  int count = 0;
  for (const Neighbour& n : input.neighbours.of(agent)) {
    if (n.distance > rules_.detection_radius) break;
    ++count;
  }
  return count;
}

bool AggregationController::isolated(std::uint32_t agent, const ControllerInput& input,
                                     const SwarmState& swarm) const {
  if (!rules_.join) {
    const std::int32_t partner = swarm.partner[agent];
    return partner == kNoPartner || previous_[partner] != AgentState::Wait;
  }
  for (const Neighbour& n : input.neighbours.of(agent)) {
    if (n.distance > rules_.detection_radius) break;
    if (previous_[n.id] == AgentState::Wait) return false;
  }
  return true;
}

void AggregationController::update_leaving(std::uint32_t agent, const ControllerInput& input,
                                           SwarmState& swarm, const CounterRng& rng) {
  swarm.leave_time_left[agent] -= rules_.dt;
  if (swarm.leave_time_left[agent] > 1e-9) {
    if (const auto away = escape_direction(agent, input)) swarm.heading[agent] = *away;
    return;
  }
  swarm.state[agent] = AgentState::Go;
  swarm.heading[agent] = random_heading(rng, input.step, agent);
}

void AggregationController::update_waiting(std::uint32_t agent, const ControllerInput& input,
                                           SwarmState& swarm, const CounterRng& rng) {
  // A pair dissolves when a partner stops waiting (SPEC 3, 4): a waiting agent that stays
  // (isolated_wait: stay) must not keep the link, or the partner's next pair would be linked
  // to it too, making one aggregate of three under join: false.
  const std::int32_t partner = swarm.partner[agent];
  if (partner != kNoPartner && previous_[partner] != AgentState::Wait) {
    swarm.partner[agent] = kNoPartner;
  }
  if (rules_.resume_when_isolated && isolated(agent, input, swarm)) {
    swarm.state[agent] = AgentState::Go;
    swarm.partner[agent] = kNoPartner;
    swarm.heading[agent] = random_heading(rng, input.step, agent);
    return;
  }
  if (!rules_.leave) return;
  const double u = rng.uniform(static_cast<std::uint64_t>(input.step), agent, Draw::Leave);
  const LeaveRule& rule = rules_.leave_rule;
  const int size = input.aggregates.size_of_agent[agent];
  const bool counts_neighbours =
      rule.law != LeaveLaw::Constant && rule.size_source == LeaveSize::Neighbours;
  const int perceived = counts_neighbours ? perceived_within_s(agent, input) : 0;
  if (u >= leave_probability(rule, size, perceived)) return;
  swarm.state[agent] = AgentState::Leave;
  swarm.partner[agent] = kNoPartner;
  swarm.leave_time_left[agent] = rules_.leave_timeout;
  if (const auto away = escape_direction(agent, input)) {
    swarm.heading[agent] = *away;
  } else if (rules_.compaction.enabled) {
    swarm.heading[agent] = random_heading(rng, input.step, agent, Draw::EnclosedLeave);
  }
}

void AggregationController::join_waiting(const ControllerInput& input, SwarmState& swarm,
                                         EventCounts& events) {
  if (!rules_.join) return;
  for (const std::uint32_t i : searchers_) {
    for (const Neighbour& nb : input.neighbours.of(i)) {
      if (nb.distance > rules_.detection_radius) break;
      if (previous_[nb.id] != AgentState::Wait) continue;
      swarm.state[i] = AgentState::Wait;
      settled_[i] = 1;
      ++events.growths;
      count_growth_by_size(input.growths_by_size, input.aggregates.size_of_agent[nb.id]);
      break;
    }
  }
}

void AggregationController::pair_searchers(const ControllerInput& input, SwarmState& swarm,
                                           EventCounts& events) {
  pairs_.clear();
  for (const std::uint32_t i : unsettled_) {
    for (const Neighbour& nb : input.neighbours.of(i)) {
      if (nb.distance > rules_.detection_radius) break;
      if (nb.id > i && searching(nb.id) && !settled_[nb.id])
        pairs_.push_back({nb.distance, i, nb.id});
    }
  }
  std::sort(pairs_.begin(), pairs_.end(), [](const SearchPair& x, const SearchPair& y) {
    if (x.distance != y.distance) return x.distance < y.distance;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  for (const SearchPair& p : pairs_) {
    if (settled_[p.a] || settled_[p.b]) continue;
    settled_[p.a] = settled_[p.b] = 2;  // 2: stopped by pairing (1: joined a waiting agent)
    swarm.state[p.a] = swarm.state[p.b] = AgentState::Wait;
    swarm.partner[p.a] = static_cast<std::int32_t>(p.b);
    swarm.partner[p.b] = static_cast<std::int32_t>(p.a);
    ++events.creations;
  }
  if (!rules_.join) return;
  // Greedy matching is maximal, so a searcher left over has only paired searchers within s.
  for (const SearchPair& p : pairs_) {
    for (const std::uint32_t agent : {p.a, p.b}) {
      if (settled_[agent]) continue;
      settled_[agent] = 1;
      swarm.state[agent] = AgentState::Wait;
      ++events.growths;
      count_growth_by_size(input.growths_by_size, 2);
    }
  }
}

void AggregationController::steer_searchers(const ControllerInput& input, SwarmState& swarm,
                                            const CounterRng& rng) {
  const auto step = static_cast<std::uint64_t>(input.step);
  for (const std::uint32_t i : unsettled_) {
    if (settled_[i]) continue;  // paired
    if (rules_.approach_radius) {
      const Neighbour* target = nullptr;
      for (const Neighbour& nb : input.neighbours.of(i)) {
        if (nb.distance > *rules_.approach_radius) break;
        if (previous_[nb.id] != AgentState::Leave && may_join(nb.id)) {
          target = &nb;
          break;
        }
      }
      if (target != nullptr && target->distance > 0.0) {
        swarm.state[i] = AgentState::Approach;
        swarm.heading[i] = target->offset * (1.0 / target->distance);
        continue;
      }
      swarm.state[i] = AgentState::Go;  // lost them: keep going the way it was heading
    }
    if (rules_.tumble > 0.0 && rng.uniform(step, i, Draw::Tumble) < rules_.tumble) {
      swarm.heading[i] = random_heading(rng, input.step, i);
    }
  }
}

// Away from the agents it perceives. Deep in a packed aggregate (compaction) the agent is
// enclosed: no direction is returned, and the agent keeps its heading, which at the start of
// the episode is drawn uniformly at random (SPEC 3). Nothing here asks where the agent
// stands: the bodies around it stop it or let it through.
std::optional<Vec2> AggregationController::escape_direction(std::uint32_t agent,
                                                            const ControllerInput& input) const {
  return heading_away(input.neighbours.of(agent), rules_.detection_radius,
                      enclosed_fraction(rules_.compaction));
}

// SPEC 3's spring force from the waiting members of the agent's aggregate it perceives
// (under join: false its partner only).
Vec2 AggregationController::compaction_velocity(std::uint32_t agent, const ControllerInput& input,
                                                const SwarmState& swarm) const {
  const std::int32_t* aggregate = input.aggregates.aggregate_of.data();
  const std::int32_t own = aggregate[agent];
  const std::int32_t partner = swarm.partner[agent];
  const AgentState* previous = previous_.data();
  const bool join = rules_.join;
  return swarmagg::compaction_velocity(rules_.compaction, input.neighbours.of(agent),
                                       rules_.detection_radius, rules_.speed, [=](AgentId id) {
                                         const bool member =
                                             join ? own >= 0 && aggregate[id] == own
                                                  : static_cast<std::int32_t>(id) == partner;
                                         return member && previous[id] == AgentState::Wait;
                                       });
}

// Overwrites the standing command of each agent that waited and goes on waiting.
void AggregationController::compact(const ControllerInput& input, const SwarmState& swarm,
                                    std::span<MotionCommand> commands) const {
  for (const std::uint32_t i : waiters_) {
    if (swarm.state[i] != AgentState::Wait) continue;
    commands[i].velocity = compaction_velocity(i, input, swarm);
  }
}

// The command of each state, looked up rather than branched on: states of neighbouring
// indices are unrelated, so a switch mispredicts about every other agent.
void AggregationController::write_commands(const SwarmState& swarm,
                                           std::span<MotionCommand> commands) const {
  constexpr SignalMask kSearching = mask_of(static_cast<Signal>(AgentState::Go)) |
                                    mask_of(static_cast<Signal>(AgentState::Approach));
  constexpr SignalMask kWaiting = mask_of(static_cast<Signal>(AgentState::Wait));
  struct StateCommand {
    std::uint64_t moving;  // all ones when the state moves along its heading
    SignalMask halt_on, blocked_by, repelled_by;
  };
  const SignalMask search_halt = kSearching | (rules_.join ? kWaiting : 0);
  const SignalMask search_block = rules_.join ? kWaiting : 0;
  const SignalMask search_block_of_waiting = rules_.join ? kSearching : 0;
  constexpr SignalMask kLeaving = mask_of(static_cast<Signal>(AgentState::Leave));
  // Moving waiting bodies (compaction) respect every body that is solid to them: they must
  // not crush a leaver they enclose, nor a searcher about to join (a contact halts only the
  // bodies it blocks, so both sides of a solid pair need the bit).
  const SignalMask wait_block =
      kWaiting | (rules_.compaction.enabled ? kLeaving | search_block_of_waiting : 0);
  constexpr std::uint64_t kMoves = ~std::uint64_t{0};
  // Indexed by AgentState: Go, Wait, Leave, Approach. Waiting bodies are solid to each
  // other, so neither compaction nor a body engine's shoving can push one through another.
  // Waiting agents stand here; compact() gives those that close up their velocity.
  const StateCommand table[kAgentStateCount] = {{kMoves, search_halt, search_block, 0},
                                                {0, 0, wait_block, 0},
                                                {kMoves, 0, kWaiting, kWaiting},
                                                {kMoves, search_halt, search_block, 0}};
  static_assert(static_cast<int>(AgentState::Go) == 0 && static_cast<int>(AgentState::Wait) == 1 &&
                static_cast<int>(AgentState::Leave) == 2 &&
                static_cast<int>(AgentState::Approach) == 3);
  const auto n = swarm.size();
  const AgentState* state = swarm.state.data();
  const Vec2* heading = swarm.heading.data();
  MotionCommand* out = commands.data();
  const double speed = rules_.speed;
  for (std::size_t i = 0; i < n; ++i) {
    const StateCommand& c = table[static_cast<std::uint8_t>(state[i]) & 3u];
    const Vec2 v = heading[i] * speed;
    // A standing agent's velocity is +0 exactly (masking, not multiplying by zero).
    const Vec2 velocity{std::bit_cast<double>(std::bit_cast<std::uint64_t>(v.x) & c.moving),
                        std::bit_cast<double>(std::bit_cast<std::uint64_t>(v.y) & c.moving)};
    out[i] = MotionCommand{velocity, c.halt_on, c.blocked_by, c.repelled_by};
  }
}

// Index lists of the agents by the state they start the decision in, filled without
// branches (each index is written to every list; only the matching list's end advances).
void AggregationController::list_by_state(std::size_t n) {
  for (IndexList* list : {&searchers_, &waiters_, &leavers_}) {
    if (list->slots.size() != n) list->slots.resize(n);
  }
  std::size_t searching = 0, waiting = 0, leaving = 0;
  const AgentState* previous = previous_.data();
  std::uint32_t* s = searchers_.slots.data();
  std::uint32_t* w = waiters_.slots.data();
  std::uint32_t* l = leavers_.slots.data();
  for (std::uint32_t i = 0; i < n; ++i) {
    const AgentState state = previous[i];
    s[searching] = w[waiting] = l[leaving] = i;
    searching += (state == AgentState::Go) | (state == AgentState::Approach);
    waiting += state == AgentState::Wait;
    leaving += state == AgentState::Leave;
  }
  searchers_.count = searching;
  waiters_.count = waiting;
  leavers_.count = leaving;
}

// The searchers that joining left searching, in index order, without branches.
void AggregationController::list_unsettled() {
  if (unsettled_.slots.size() != searchers_.slots.size())
    unsettled_.slots.resize(searchers_.slots.size());
  std::size_t count = 0;
  std::uint32_t* out = unsettled_.slots.data();
  for (const std::uint32_t i : searchers_) {
    out[count] = i;
    count += settled_[i] == 0;
  }
  unsettled_.count = count;
}

void AggregationController::decide(const ControllerInput& input, SwarmState& swarm,
                                   const CounterRng& rng, std::span<MotionCommand> commands,
                                   EventCounts& events) {
  const auto n = static_cast<std::uint32_t>(swarm.size());
  previous_.assign(swarm.state.begin(), swarm.state.end());
  settled_.assign(n, 0);
  // assign() reallocates to the exact size whenever it grows, which is every step while
  // aggregates form; room for the most there can be (two members each) is reserved once.
  if (leavers_left_.capacity() < n / 2) leavers_left_.reserve(n / 2);
  leavers_left_.assign(input.aggregates.sizes.begin(), input.aggregates.sizes.end());
  turn_at_walls(input.reflections, swarm);
  list_by_state(n);
  // Leaving and waiting agents decide from the previous states only, so each group can be
  // walked on its own (in index order, as leave events are counted in that order).
  for (const std::uint32_t i : leavers_) update_leaving(i, input, swarm, rng);
  for (const std::uint32_t i : waiters_) {
    update_waiting(i, input, swarm, rng);
    if (swarm.state[i] == AgentState::Leave)
      count_leave(input.aggregates.aggregate_of[i], leavers_left_, events);
  }
  join_waiting(input, swarm, events);
  list_unsettled();
  pair_searchers(input, swarm, events);
  steer_searchers(input, swarm, rng);
  write_commands(swarm, commands);
  if (rules_.compaction.enabled) compact(input, swarm, commands);
}

}  // namespace swarmagg
