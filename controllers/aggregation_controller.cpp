#include "controllers/aggregation_controller.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/agents_in_state.hpp"

namespace swarmagg {
namespace {

// The signals of searching agents (GO and APPROACH).
constexpr SignalMask kSearching = mask_of(static_cast<Signal>(AgentState::Go)) |
                                  mask_of(static_cast<Signal>(AgentState::Approach));
// settled_ of a searcher that stopped in this decision: it joined waiting agents or a pair
// just formed (a growth), or it formed a pair with another searcher.
constexpr std::uint8_t kJoined = 1;
constexpr std::uint8_t kPaired = 2;

}  // namespace

bool AggregationController::searching(std::uint32_t agent) const {
  return previous_[agent] == AgentState::Go || previous_[agent] == AgentState::Approach;
}

bool AggregationController::may_join(std::uint32_t agent) const {
  return searching(agent) || (rules_.join && previous_[agent] == AgentState::Wait);
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

// Each agent that starts the decision waiting, in index order (leave events are counted in
// that order). Its neighbour list is read once, for isolation, the perceived count and the
// compaction force; the force applies if it goes on waiting, as nothing later in the decision
// changes a waiting agent's state or partner.
void AggregationController::update_waiting(const ControllerInput& input, SwarmState& swarm,
                                           const CounterRng& rng, EventCounts& events) {
  // The switches that hold for the whole decision are template arguments, so that the
  // per-agent loop carries no test of them.
  const bool compacts = rules_.compaction.enabled;
  if (rules_.join) {
    if (compacts) return update_waiting_as<true, true>(input, swarm, rng, events);
    return update_waiting_as<true, false>(input, swarm, rng, events);
  }
  if (compacts) return update_waiting_as<false, true>(input, swarm, rng, events);
  update_waiting_as<false, false>(input, swarm, rng, events);
}

template <bool kJoin, bool kCompaction>
void AggregationController::update_waiting_as(const ControllerInput& input, SwarmState& swarm,
                                              const CounterRng& rng, EventCounts& events) {
  const StepRng draws = rng.at_step(static_cast<std::uint64_t>(input.step));
  const AgentState* previous = previous_.data();
  const std::int32_t* aggregate = input.aggregates.aggregate_of.data();
  const NeighbourLists& neighbours = input.neighbours;
  const double radius = rules_.detection_radius;
  const CompactionRule& compaction = rules_.compaction;
  // The members that pull are the waiting agents of its aggregate (none when it is in none),
  // under join: false its waiting partner only: a waiting neighbour whose key (aggregate, or
  // index) is the agent's own key. No key is below -1, so kNoMembers matches nobody.
  constexpr std::int32_t kNoMembers = std::numeric_limits<std::int32_t>::min();
  // The view is gathered in locals, which the compiler keeps in registers.
  const auto look_around = [&](std::uint32_t agent, std::int32_t partner) {
    const std::int32_t own = kJoin ? aggregate[agent] : partner;  // negative: none
    const std::int32_t own_key = own >= 0 ? own : kNoMembers;
    int perceived = 0;
    bool sees_waiting = false;
    Vec2 force;
    for (const Neighbour& nb : neighbours.of(agent)) {
      if (nb.distance > radius) break;
      ++perceived;
      const bool waited = previous[nb.id] == AgentState::Wait;
      sees_waiting |= waited;
      if constexpr (kCompaction) {
        const std::int32_t key = kJoin ? aggregate[nb.id] : static_cast<std::int32_t>(nb.id);
        if (waited & (key == own_key)) add_spring_force(compaction, nb, force);
      }
    }
    return WaitingView{perceived, sees_waiting, force};
  };
  if (movers_.size() != swarm.size()) movers_.resize(swarm.size());
  Mover* movers = movers_.data();
  std::size_t mover_count = 0;
  const bool views_stand = views_stand_for(input, swarm);
  for (const std::uint32_t agent : waiters_) {
    const std::int32_t partner = swarm.partner[agent];
    // A view just looked at is used as computed, not read back from views_: that read would
    // wait for the store, which in a large swarm misses the cache.
    const WaitingView view = views_stand ? views_[agent] : look_around(agent, partner);
    if (!views_stand) views_[agent] = view;
    // A pair dissolves when a partner stops waiting (docs/controllers.md): a waiting agent that
    // stays (isolated_wait: stay) must not keep the link, or the partner's next pair would be
    // linked to it too, making one aggregate of three under join: false.
    // Without a partner, its own state is read in the partner's place: selected by a mask,
    // as whether a waiting agent has a partner is a coin toss to the branch predictor.
    const bool has_partner = partner != kNoPartner;
    const std::uint32_t partner_mask = 0u - static_cast<std::uint32_t>(has_partner);
    const std::uint32_t partner_or_self =
        (static_cast<std::uint32_t>(partner) & partner_mask) | (agent & ~partner_mask);
    const bool partner_waits = has_partner & (previous[partner_or_self] == AgentState::Wait);
    if (partner != kNoPartner && !partner_waits) swarm.partner[agent] = kNoPartner;
    const bool isolated = kJoin ? !view.sees_waiting : !partner_waits;
    if (rules_.resume_when_isolated && isolated) {
      swarm.state[agent] = AgentState::Go;
      swarm.partner[agent] = kNoPartner;
      swarm.heading[agent] = random_heading(rng, input.step, agent);
      continue;
    }
    if (rules_.leave) {
      const double u = draws.uniform(agent, Draw::Leave);
      if (u < leave_chance(input.aggregates.size_of_agent[agent], view.perceived)) {
        swarm.state[agent] = AgentState::Leave;
        swarm.partner[agent] = kNoPartner;
        swarm.leave_time_left[agent] = rules_.leave_timeout;
        if (const auto away = escape_direction(agent, input)) {
          swarm.heading[agent] = *away;
        } else if (kCompaction) {
          swarm.heading[agent] = random_heading(rng, input.step, agent, Draw::EnclosedLeave);
        }
        count_leave(input.aggregates.aggregate_of[agent], leavers_left_, events);
        continue;
      }
    }
    // Goes on waiting. Most stand (force below the tolerance), and write_commands gives them
    // +0; the rest move at random to the branch predictor, so each is written to the next
    // slot, which only those that may move keep (squared forces below standing_norm2_
    // surely stand).
    if constexpr (kCompaction) {
      movers[mover_count] = {agent, view.force};
      mover_count += !(norm2(view.force) < standing_norm2_);
    }
  }
  mover_count_ = mover_count;
}

// A waiting agent's view reads only the neighbour lists, the states the decision starts from,
// the aggregate labels and its partner: while all of these are the ones the views were
// computed from, so are the views (a packed aggregate at rest reads no list). Otherwise they
// are computed anew, and remembered with what they were read from.
bool AggregationController::views_stand_for(const ControllerInput& input, const SwarmState& swarm) {
  const std::span<const std::int32_t> labels = input.aggregates.aggregate_of;
  const bool stand =
      views_lists_ == &input.neighbours && views_generation_ == input.neighbours.generation() &&
      std::ranges::equal(views_states_, previous_) && std::ranges::equal(views_labels_, labels) &&
      std::ranges::equal(views_partners_, swarm.partner);
  if (stand) return true;
  views_.resize(swarm.size());
  // Remembering costs copies; they pay only in a world at rest, whose lists stayed since the
  // last decision. In a moving world the views are forgotten instead.
  const bool lists_stayed =
      seen_lists_ == &input.neighbours && seen_generation_ == input.neighbours.generation();
  seen_lists_ = &input.neighbours;
  seen_generation_ = input.neighbours.generation();
  views_lists_ = lists_stayed ? &input.neighbours : nullptr;
  if (!lists_stayed) return false;
  views_generation_ = input.neighbours.generation();
  views_states_.assign(previous_.begin(), previous_.end());
  views_labels_.assign(labels.begin(), labels.end());
  views_partners_.assign(swarm.partner.begin(), swarm.partner.end());
  return false;
}

// Each searcher's list is read once: it joins the first waiting agent it perceives within s
// (when joining is allowed), and the searchers within s that it could pair with are gathered
// on the way (pair_searchers drops those where either side joined).
void AggregationController::join_waiting(const ControllerInput& input, SwarmState& swarm,
                                         EventCounts& events) {
  pairs_.clear();
  const AgentState* previous = previous_.data();
  const double radius = rules_.detection_radius;
  const bool join = rules_.join;
  for (const std::uint32_t i : searchers_) {
    for (const Neighbour& nb : input.neighbours.of(i)) {
      if (nb.distance > radius) break;
      if (join && previous[nb.id] == AgentState::Wait) {
        swarm.state[i] = AgentState::Wait;
        settled_[i] = kJoined;
        ++events.growths;
        count_growth_by_size(input.growths_by_size, input.aggregates.size_of_agent[nb.id]);
        break;
      }
      if (nb.id > i && searching(nb.id)) pairs_.push_back({nb.distance, i, nb.id});
    }
  }
}

void AggregationController::pair_searchers(const ControllerInput& input, SwarmState& swarm,
                                           EventCounts& events) {
  std::erase_if(pairs_, [&](const SearchPair& p) { return settled_[p.a] || settled_[p.b]; });
  std::sort(pairs_.begin(), pairs_.end(), [](const SearchPair& x, const SearchPair& y) {
    if (x.distance != y.distance) return x.distance < y.distance;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  for (const SearchPair& p : pairs_) {
    if (settled_[p.a] || settled_[p.b]) continue;
    settled_[p.a] = settled_[p.b] = kPaired;
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
      settled_[agent] = kJoined;
      swarm.state[agent] = AgentState::Wait;
      ++events.growths;
      count_growth_by_size(input.growths_by_size, 2);
    }
  }
}

void AggregationController::steer_searchers(const ControllerInput& input, SwarmState& swarm,
                                            const CounterRng& rng) {
  // Bayindir's searchers neither approach nor tumble: they keep their heading.
  const bool tumbles = rules_.tumble > 0.0;
  if (!rules_.approach_radius && !tumbles) return;
  const StepRng draws = rng.at_step(static_cast<std::uint64_t>(input.step));
  for (const std::uint32_t i : searchers_) {
    if (settled_[i]) continue;  // joined or paired
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
    if (tumbles && draws.uniform(i, Draw::Tumble) < rules_.tumble) {
      swarm.heading[i] = random_heading(rng, input.step, i);
    }
  }
}

// A meeting halts both sides, as two searchers' does: a member closing up stops for the rest
// of the step where a searcher that may join comes within s, and stands in the step after,
// in which the searcher joins (its force, from the states before, does not count the
// newcomer yet). Otherwise a member creeping inward could leave the searcher just beyond s:
// halted at s, the searcher would see nobody within s and approach again, step after step
// (counting an encounter each time), or, having joined, find itself alone and search again.
void AggregationController::close_up(const ControllerInput& input,
                                     std::span<MotionCommand> commands) const {
  const SignalMask closing_halt = rules_.join ? kSearching : 0;
  for (std::size_t k = 0; k < mover_count_; ++k) {
    const Mover& m = movers_[k];
    if (joined_beside(m.agent, input)) continue;  // stands, as write_commands left it
    MotionCommand& command = commands[m.agent];
    command.velocity = spring_velocity(rules_.compaction, m.force, norm(m.force), rules_.speed);
    if (!is_zero(command.velocity)) command.halt_on = closing_halt;
  }
}

bool AggregationController::joined_beside(std::uint32_t agent, const ControllerInput& input) const {
  for (const Neighbour& nb : input.neighbours.of(agent)) {
    if (nb.distance > rules_.detection_radius) return false;
    if (settled_[nb.id] == kJoined) return true;
  }
  return false;
}

// Away from the agents it perceives. Deep in a packed aggregate (compaction) the agent is
// enclosed: no direction is returned, and the agent keeps its heading, which at the start of
// the episode is drawn uniformly at random (docs/controllers.md). Nothing here asks where the agent
// stands: the bodies around it stop it or let it through.
std::optional<Vec2> AggregationController::escape_direction(std::uint32_t agent,
                                                            const ControllerInput& input) const {
  return heading_away(input.neighbours.of(agent), rules_.detection_radius,
                      enclosed_fraction(rules_.compaction));
}

// The command of each state, looked up rather than branched on: states of neighbouring
// indices are unrelated, so a switch mispredicts about every other agent.
void AggregationController::write_commands(const SwarmState& swarm,
                                           std::span<MotionCommand> commands) const {
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
  // not crush a leaver they enclose, nor a searcher about to join. (Either side's bit makes a
  // pair solid; the waiting side names them as well, so that its mask reads as the rule.)
  const SignalMask wait_block =
      kWaiting | (rules_.compaction.enabled ? kLeaving | search_block_of_waiting : 0);
  constexpr std::uint64_t kMoves = ~std::uint64_t{0};
  // Indexed by AgentState: Go, Wait, Leave, Approach. Waiting bodies are solid to each
  // other, so neither compaction nor a body engine's shoving can push one through another.
  // Waiting agents stand here; those that close up (movers_) get their velocity after.
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

// Index lists of the agents by the state they start the decision in, sixteen agents at a
// time without branches (core/agents_in_state.hpp).
void AggregationController::list_by_state(std::size_t n) {
  const std::span<const AgentState> previous(previous_.data(), n);
  for (IndexList* list : {&searchers_, &waiters_, &leavers_}) {
    if (list->slots.size() != n) list->slots.resize(n);
  }
  searchers_.count = list_agents_in_states(previous, AgentState::Go, AgentState::Approach,
                                           searchers_.slots.data());
  waiters_.count = list_agents_in_state(previous, AgentState::Wait, waiters_.slots.data());
  leavers_.count = list_agents_in_state(previous, AgentState::Leave, leavers_.slots.data());
}

namespace {

template <typename T, typename U>
bool same_bytes(std::span<const T> a, std::span<const U> b) {
  static_assert(sizeof(T) == sizeof(U));
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size_bytes()) == 0;
}

bool all_zero(std::span<const std::uint8_t> bytes) {
  return std::ranges::all_of(bytes, [](std::uint8_t b) { return b == 0; });
}

}  // namespace

bool AggregationController::repeat_steady(const ControllerInput& input, const SwarmState& swarm,
                                          const CounterRng& rng,
                                          std::span<MotionCommand> commands) const {
  const SteadyDecision& s = steady_;
  const std::size_t n = swarm.size();
  const bool same_inputs =
      s.valid && s.lists == &input.neighbours && s.generation == input.neighbours.generation() &&
      commands.size() == n && same_bytes<AgentState, AgentState>(swarm.state, previous_) &&
      same_bytes<std::int32_t, std::int32_t>(swarm.partner, s.partners) &&
      same_bytes<std::int32_t, std::int32_t>(input.aggregates.aggregate_of, s.labels) &&
      same_bytes<std::int32_t, std::int32_t>(input.aggregates.size_of_agent, s.sizes) &&
      all_zero(input.reflections);
  if (!same_inputs) return false;
  if (rules_.leave) {
    const StepRng draws = rng.at_step(static_cast<std::uint64_t>(input.step));
    if (leave_same_for_all_) {
      // Every draw is taken (no early exit): which one fires is a coin toss to the predictor.
      bool fires = false;
      for (std::uint32_t agent = 0; agent < n; ++agent) {
        fires |= (draws.bits(agent, Draw::Leave) >> 11) < leave_draws_below_;
      }
      if (fires) return false;
    } else {
      const std::int32_t* size = input.aggregates.size_of_agent.data();
      for (std::uint32_t agent = 0; agent < n; ++agent) {
        if (draws.uniform(agent, Draw::Leave) < leave_chance(size[agent], views_[agent].perceived))
          return false;
      }
    }
  }
  std::ranges::copy(s.commands, commands.begin());
  return true;
}

// Steady: every agent started waiting and still waits (so no partner was dropped and no
// heading turned), no wall turned anyone, and the views (views_) are those of these inputs.
void AggregationController::remember_if_steady(const ControllerInput& input,
                                               const SwarmState& swarm,
                                               std::span<const MotionCommand> commands) {
  SteadyDecision& s = steady_;
  const std::size_t n = swarm.size();
  s.valid = n > 0 && waiters_.count == n &&
            same_bytes<AgentState, AgentState>(swarm.state, previous_) &&
            all_zero(input.reflections);
  if (!s.valid) return;
  s.lists = &input.neighbours;
  s.generation = input.neighbours.generation();
  s.labels.assign(input.aggregates.aggregate_of.begin(), input.aggregates.aggregate_of.end());
  s.sizes.assign(input.aggregates.size_of_agent.begin(), input.aggregates.size_of_agent.end());
  s.partners.assign(swarm.partner.begin(), swarm.partner.end());
  s.commands.assign(commands.begin(), commands.end());
}

void AggregationController::decide(const ControllerInput& input, SwarmState& swarm,
                                   const CounterRng& rng, std::span<MotionCommand> commands,
                                   EventCounts& events) {
  if (repeat_steady(input, swarm, rng, commands)) return;
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
  // walked on its own.
  for (const std::uint32_t i : leavers_) update_leaving(i, input, swarm, rng);
  update_waiting(input, swarm, rng, events);
  join_waiting(input, swarm, events);
  pair_searchers(input, swarm, events);
  steer_searchers(input, swarm, rng);
  write_commands(swarm, commands);
  close_up(input, commands);
  remember_if_steady(input, swarm, commands);
}

}  // namespace swarmagg
