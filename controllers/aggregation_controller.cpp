#include "controllers/aggregation_controller.hpp"

#include <algorithm>
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
    swarm.heading[agent] = escape_direction(agent, input, swarm.heading[agent]);
    return;
  }
  swarm.state[agent] = AgentState::Go;
  swarm.heading[agent] = random_heading(rng, input.step, agent);
}

void AggregationController::update_waiting(std::uint32_t agent, const ControllerInput& input,
                                           SwarmState& swarm, const CounterRng& rng) {
  if (rules_.resume_when_isolated && isolated(agent, input, swarm)) {
    swarm.state[agent] = AgentState::Go;
    swarm.partner[agent] = kNoPartner;
    swarm.heading[agent] = random_heading(rng, input.step, agent);
    return;
  }
  if (!rules_.leave) return;
  const double u = rng.uniform(static_cast<std::uint64_t>(input.step), agent, Draw::Leave);
  const LeaveRule& rule = rules_.leave_rule;
  const int size = input.aggregates.size_of_agent()[agent];
  const bool counts_neighbours = rule.law != LeaveLaw::Constant && rule.size_source == LeaveSize::Neighbours;
  const int perceived = counts_neighbours ? perceived_within_s(agent, input) : 0;
  if (u >= leave_probability(rule, size, perceived)) return;
  swarm.state[agent] = AgentState::Leave;
  swarm.partner[agent] = kNoPartner;
  swarm.leave_time_left[agent] = rules_.leave_timeout;
  swarm.heading[agent] = escape_direction(agent, input, swarm.heading[agent]);
}

// Members of one aggregate leaving in the same step are counted one after another: an
// aggregate of two that both leave dissipates once; of five losing two, shrinks twice.
void AggregationController::count_leave(std::uint32_t agent, const ControllerInput& input,
                                        EventCounts& events) {
  const std::int32_t aggregate = input.aggregates.aggregate_of()[agent];
  if (aggregate < 0) return;
  std::int32_t& left = leavers_left_[aggregate];
  if (left >= 3) ++events.shrinks;
  if (left == 2) ++events.dissipations;
  --left;
}

void AggregationController::join_waiting(const ControllerInput& input, SwarmState& swarm,
                                         EventCounts& events) {
  if (!rules_.join) return;
  const auto n = static_cast<std::uint32_t>(swarm.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!searching(i)) continue;
    for (const Neighbour& nb : input.neighbours.of(i)) {
      if (nb.distance > rules_.detection_radius) break;
      if (previous_[nb.id] != AgentState::Wait) continue;
      swarm.state[i] = AgentState::Wait;
      settled_[i] = 1;
      ++events.growths;
      break;
    }
  }
}

void AggregationController::pair_searchers(const ControllerInput& input, SwarmState& swarm,
                                           EventCounts& events) {
  const auto n = static_cast<std::uint32_t>(swarm.size());
  pairs_.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!searching(i) || settled_[i]) continue;
    for (const Neighbour& nb : input.neighbours.of(i)) {
      if (nb.distance > rules_.detection_radius) break;
      if (nb.id > i && searching(nb.id) && !settled_[nb.id]) pairs_.push_back({nb.distance, i, nb.id});
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
    }
  }
}

void AggregationController::steer_searchers(const ControllerInput& input, SwarmState& swarm,
                                            const CounterRng& rng) {
  const auto n = static_cast<std::uint32_t>(swarm.size());
  const auto step = static_cast<std::uint64_t>(input.step);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!searching(i) || settled_[i]) continue;
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

Vec2 AggregationController::escape_direction(std::uint32_t agent, const ControllerInput& input,
                                             Vec2 fallback) const {
  Vec2 towards;
  for (const Neighbour& nb : input.neighbours.of(agent)) {
    if (nb.distance > rules_.detection_radius) break;
    towards += nb.offset;
  }
  const double length = norm(towards);
  return length > 1e-12 ? towards * (-1.0 / length) : fallback;
}

MotionCommand AggregationController::command_for(std::uint32_t agent,
                                                 const SwarmState& swarm) const {
  constexpr SignalMask kSearching =
      mask_of(static_cast<Signal>(AgentState::Go)) | mask_of(static_cast<Signal>(AgentState::Approach));
  constexpr SignalMask kWaiting = mask_of(static_cast<Signal>(AgentState::Wait));
  MotionCommand c;
  switch (swarm.state[agent]) {
    case AgentState::Go:
    case AgentState::Approach:
      c.velocity = swarm.heading[agent] * rules_.speed;
      c.halt_on = kSearching | (rules_.join ? kWaiting : 0);
      c.blocked_by = rules_.join ? kWaiting : 0;
      break;
    case AgentState::Wait:
      // Waiting bodies are solid to each other, so a body engine cannot shove one through
      // another and loosen the aggregate (kinematic waiting agents never move anyway).
      c.blocked_by = kWaiting;
      break;
    case AgentState::Leave:
      c.velocity = swarm.heading[agent] * rules_.speed;
      c.blocked_by = kWaiting;
      c.repelled_by = kWaiting;
      break;
  }
  return c;
}

void AggregationController::decide(const ControllerInput& input, SwarmState& swarm,
                                   const CounterRng& rng, std::span<MotionCommand> commands,
                                   EventCounts& events) {
  const auto n = static_cast<std::uint32_t>(swarm.size());
  previous_.assign(swarm.state.begin(), swarm.state.end());
  settled_.assign(n, 0);
  leavers_left_.assign(input.aggregates.sizes().begin(), input.aggregates.sizes().end());
  turn_at_walls(input.reflections, swarm);
  for (std::uint32_t i = 0; i < n; ++i) {
    if (previous_[i] == AgentState::Leave) update_leaving(i, input, swarm, rng);
    if (previous_[i] != AgentState::Wait) continue;
    update_waiting(i, input, swarm, rng);
    if (swarm.state[i] == AgentState::Leave) count_leave(i, input, events);
  }
  join_waiting(input, swarm, events);
  pair_searchers(input, swarm, events);
  steer_searchers(input, swarm, rng);
  for (std::uint32_t i = 0; i < n; ++i) commands[i] = command_for(i, swarm);
}

}  // namespace swarmagg
