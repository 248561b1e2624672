#include "controllers/cockroach/cockroach_controller.hpp"

#include <algorithm>

#include "control_interface/joined_size.hpp"
#include "control_interface/state_signals.hpp"

namespace swarmagg {
namespace {

// This controller's own random purpose: distinct from every core Draw, so its stop draws are
// independent of the leave, heading and tumble draws of the same agent and step.
constexpr Draw kStopDraw = static_cast<Draw>(0x636b);  // "ck"

}  // namespace

double CockroachController::entry(const std::vector<double>& list, std::size_t n) {
  return list[std::min(n, list.size() - 1)];
}

int CockroachController::waiting_perceived(std::uint32_t agent,
                                           const ControllerInput& input) const {
  int count = 0;
  for (const Neighbour& nb : input.neighbours.of(agent)) {
    if (nb.distance > parameters_.detection_radius) break;  // nearest first
    count += previous_[nb.id] == AgentState::Wait;
  }
  return count;
}

// The size of the aggregate of the nearest waiting agent `agent` perceives (the one it joins).
int CockroachController::joined_size(std::uint32_t agent, const ControllerInput& input) const {
  return joined_aggregate_size(input.neighbours.of(agent), parameters_.detection_radius, previous_,
                               input.aggregates.size_of_agent);
}

// Away from the agents it perceives; enclosed in a packed aggregate (compaction), a random
// heading, and the bodies around it decide whether it gets out (docs/controllers.md).
void CockroachController::leave(std::uint32_t agent, const ControllerInput& input,
                                SwarmState& swarm, const CounterRng& rng) {
  swarm.state[agent] = AgentState::Leave;
  swarm.leave_time_left[agent] = parameters_.leave_timeout;
  const CompactionRule& compaction = parameters_.compaction;
  if (const auto away = heading_away(input.neighbours.of(agent), parameters_.detection_radius,
                                     enclosed_fraction(compaction))) {
    swarm.heading[agent] = *away;
  } else if (compaction.enabled) {
    swarm.heading[agent] = random_heading(rng, input.step, agent, Draw::EnclosedLeave);
  }
}

void CockroachController::pair_searchers(SwarmState& swarm, EventCounts& events) {
  std::sort(pairs_.begin(), pairs_.end(), [](const SearchPair& x, const SearchPair& y) {
    if (x.distance != y.distance) return x.distance < y.distance;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  for (const SearchPair& p : pairs_) {
    if (stopped_[p.a] || stopped_[p.b]) continue;
    stopped_[p.a] = stopped_[p.b] = 1;
    swarm.state[p.a] = swarm.state[p.b] = AgentState::Wait;
    ++events.creations;
  }
}

void CockroachController::write_commands(const SwarmState& swarm,
                                         std::span<MotionCommand> commands) const {
  constexpr SignalMask kGo = mask_of(signal_of(AgentState::Go));
  constexpr SignalMask kWait = mask_of(signal_of(AgentState::Wait));
  constexpr SignalMask kLeave = mask_of(signal_of(AgentState::Leave));
  // Waiting bodies that close up (compaction) respect every body solid to them: they must
  // not crush a leaver they enclose nor a searcher beside them. (Either side's bit makes a
  // pair solid; the waiting side names them as well, so that its mask reads as the rule.)
  const SignalMask wait_block = kWait | (parameters_.compaction.enabled ? kLeave | kGo : 0);
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const Vec2 moving = swarm.heading[i] * parameters_.speed;
    switch (swarm.state[i]) {
      case AgentState::Wait:
        commands[i] = MotionCommand{{0.0, 0.0}, 0, wait_block, 0};
        break;
      case AgentState::Leave:
        commands[i] = MotionCommand{moving, 0, kWait, kWait};
        break;
      default:  // searching: halt where another searcher comes within s (to pair up there)
        commands[i] = MotionCommand{moving, kGo, kWait, 0};
        break;
    }
  }
}

// The spring force of docs/controllers.md from the waiting members of its aggregate that each agent
// that waited and goes on waiting perceives.
void CockroachController::compact(const ControllerInput& input, const SwarmState& swarm,
                                  std::span<MotionCommand> commands) const {
  const std::int32_t* aggregate = input.aggregates.aggregate_of.data();
  const AgentState* previous = previous_.data();
  for (std::uint32_t i = 0; i < swarm.size(); ++i) {
    if (previous[i] != AgentState::Wait || swarm.state[i] != AgentState::Wait) continue;
    const std::int32_t own = aggregate[i];
    if (own < 0) continue;
    commands[i].velocity = compaction_velocity(
        parameters_.compaction, input.neighbours.of(i), parameters_.detection_radius,
        parameters_.speed,
        [=](AgentId id) { return aggregate[id] == own && previous[id] == AgentState::Wait; });
  }
}

void CockroachController::decide(const ControllerInput& input, SwarmState& swarm,
                                 const CounterRng& rng, std::span<MotionCommand> commands,
                                 EventCounts& events) {
  const auto n = static_cast<std::uint32_t>(swarm.size());
  const auto step = static_cast<std::uint64_t>(input.step);
  previous_.assign(swarm.state.begin(), swarm.state.end());
  stopped_.assign(n, 0);
  leavers_left_.assign(input.aggregates.sizes.begin(), input.aggregates.sizes.end());
  pairs_.clear();
  turn_at_walls(input.reflections, swarm);
  for (std::uint32_t i = 0; i < n; ++i) {
    switch (previous_[i]) {
      case AgentState::Leave:
        swarm.leave_time_left[i] -= parameters_.dt;
        if (swarm.leave_time_left[i] > 1e-9) {
          if (const auto away = heading_away(input.neighbours.of(i), parameters_.detection_radius,
                                             enclosed_fraction(parameters_.compaction)))
            swarm.heading[i] = *away;
        } else {
          swarm.state[i] = AgentState::Go;
          swarm.heading[i] = random_heading(rng, input.step, i);
        }
        break;
      case AgentState::Wait: {
        const auto waiting = static_cast<std::size_t>(waiting_perceived(i, input));
        if (rng.uniform(step, i, Draw::Leave) < entry(parameters_.leave_probability, waiting)) {
          leave(i, input, swarm, rng);
          count_leave(input.aggregates.aggregate_of[i], leavers_left_, events);
        }
        break;
      }
      default: {
        const int waiting = waiting_perceived(i, input);
        if (waiting == 0) {
          for (const Neighbour& nb : input.neighbours.of(i)) {
            if (nb.distance > parameters_.detection_radius) break;
            if (nb.id > i && previous_[nb.id] == AgentState::Go &&
                waiting_perceived(nb.id, input) == 0)
              pairs_.push_back({nb.distance, i, nb.id});
          }
          break;
        }
        const double p = entry(parameters_.stop_probability, static_cast<std::size_t>(waiting - 1));
        if (rng.uniform(step, i, kStopDraw) < p) {
          swarm.state[i] = AgentState::Wait;
          stopped_[i] = 1;
          ++events.growths;
          count_growth_by_size(input.growths_by_size, joined_size(i, input));
        } else if (const auto away =
                       heading_away(input.neighbours.of(i), parameters_.detection_radius, 0.0)) {
          // Walks on: away from the agents it met, so it does not push into them.
          swarm.heading[i] = *away;
        }
        break;
      }
    }
  }
  pair_searchers(swarm, events);
  write_commands(swarm, commands);
  if (parameters_.compaction.enabled) compact(input, swarm, commands);
}

}  // namespace swarmagg
