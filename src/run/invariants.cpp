#include "run/invariants.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "config/world_keys.hpp"
#include "geometry/arena_geometry.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// Relative rounding allowed where an engine is exact (positions are sums of doubles).
constexpr double kRounding = 1e-9;

[[noreturn]] void violated(const CheckedState& s, const std::string& what) {
  throw InvariantViolation("invariant violated in replicate " + std::to_string(s.replicate) +
                           " at step " + std::to_string(s.step) + ": " + what);
}

std::string point(Vec2 p) {
  return "(" + format_number(p.x) + ", " + format_number(p.y) + ")";
}

std::string agent(const CheckedState& s, std::size_t i) {
  const auto state = static_cast<int>(s.swarm.state[i]);
  const std::string name = state < kAgentStateCount ? std::string(to_string(s.swarm.state[i]))
                                                    : "state " + std::to_string(state);
  return "agent " + std::to_string(i) + " (" + name + ")";
}

bool box2d(const WorldSpec& spec) {
  return spec.engine.type == EngineType::Box2D;
}

double longest_side(const WorldSpec& spec) {
  return std::max({spec.arena.width, spec.arena.height, 1.0});
}

void check_sizes(const CheckedState& s) {
  const auto n = static_cast<std::size_t>(s.spec.robots.count);
  const auto expect = [&](const char* what, std::size_t size) {
    if (size == n) return;
    violated(s, std::string(what) + " holds " + std::to_string(size) + " agents, the world " +
                    std::to_string(n));
  };
  expect("the engine", s.positions.size());
  expect("the neighbour lists", s.neighbours.agent_count());
  expect("the controller state", s.swarm.state.size());
  expect("the headings", s.swarm.heading.size());
  expect("the leave timers", s.swarm.leave_time_left.size());
  expect("the partners", s.swarm.partner.size());
  expect("the aggregate labels", s.aggregates.aggregate_of().size());
  expect("the aggregate sizes", s.aggregates.size_of_agent().size());
}

void check_positions(const CheckedState& s) {
  const ArenaSpec& arena = s.spec.arena;
  // Walls keep each centre r from them; Box2D resolves wall contacts with some give.
  const double r = s.spec.robots.radius;
  const double give = box2d(s.spec) ? 0.5 * r : kRounding * longest_side(s.spec);
  const double margin = arena.topology == Topology::Walls ? r - give : 0.0;
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    const Vec2 p = s.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      violated(s, agent(s, i) + " has a non-finite position " + point(p));
    }
    if (p.x < margin || p.x > arena.width - margin || p.y < margin || p.y > arena.height - margin) {
      violated(s, agent(s, i) + " at " + point(p) + " is outside the " +
                      format_number(arena.width) + " x " + format_number(arena.height) +
                      " arena (centres at least " + format_number(margin) + " from its edges)");
    }
  }
}

void check_agent(const CheckedState& s, std::size_t i) {
  const AgentState state = s.swarm.state[i];
  if (static_cast<int>(state) >= kAgentStateCount) violated(s, agent(s, i) + " has no valid state");
  if (!s.rules.allows(state)) {
    violated(s, agent(s, i) + " is in a state this world's rules never enter");
  }
  const Vec2 h = s.swarm.heading[i];
  if (!std::isfinite(h.x) || !std::isfinite(h.y) || std::fabs(norm(h) - 1.0) > 1e-6) {
    violated(s, agent(s, i) + " has heading " + point(h) + ", not a unit vector");
  }
  const double timeout = s.spec.controller.leave_timeout;
  const double left = s.swarm.leave_time_left[i];
  const double slack = kRounding * (1.0 + timeout);
  if (state == AgentState::Leave && !(left >= -slack && left <= timeout + slack)) {
    violated(s, agent(s, i) + " has " + format_number(left) +
                    " tu of LEAVE left, outside [0, leave_timeout = " + format_number(timeout) +
                    "]");
  }
  const std::int32_t partner = s.swarm.partner[i];
  if (partner != kNoPartner &&
      (partner < 0 || partner >= static_cast<std::int32_t>(s.swarm.size()) ||
       partner == static_cast<std::int32_t>(i))) {
    violated(s, agent(s, i) + " has partner " + std::to_string(partner));
  }
}

void check_agents(const CheckedState& s) {
  for (std::size_t i = 0; i < s.swarm.size(); ++i) check_agent(s, i);
}

// Linked WAIT agents must share an aggregate (the tracker's links, observers/aggregate_tracker).
void check_links(const CheckedState& s) {
  const auto label = s.aggregates.aggregate_of();
  const bool partners = s.rules.partners_only;
  const double reach = s.spec.robots.detection_radius;
  const auto same = [&](std::size_t i, std::size_t j) {
    if (label[i] >= 0 && label[i] == label[j]) return;
    violated(s, agent(s, i) + " and " + agent(s, j) + " are linked but in aggregates " +
                    std::to_string(label[i]) + " and " + std::to_string(label[j]));
  };
  for (std::size_t i = 0; i < s.swarm.size(); ++i) {
    if (s.swarm.state[i] != AgentState::Wait) continue;
    if (partners) {
      const std::int32_t p = s.swarm.partner[i];
      if (p != kNoPartner && s.swarm.state[p] == AgentState::Wait) same(i, p);
      continue;
    }
    for (const Neighbour& nb : s.neighbours.of(static_cast<AgentId>(i))) {
      if (nb.distance > reach) break;  // nearest first
      if (s.swarm.state[nb.id] == AgentState::Wait) same(i, nb.id);
    }
  }
}

void check_events(const CheckedState& s, int waiting) {
  const EventCounts& e = s.events;
  const auto show = [&] {
    return " (creations " + std::to_string(e.creations) + ", growths " + std::to_string(e.growths) +
           ", dissipations " + std::to_string(e.dissipations) + ", shrinks " +
           std::to_string(e.shrinks) + ", waiting " + std::to_string(waiting) + ")";
  };
  if (2 * e.creations + e.growths <
      static_cast<std::uint64_t>(waiting) + e.dissipations + e.shrinks) {
    violated(s,
             "2 creations + growths do not account for the waiting agents plus the counted "
             "leaves" +
                 show());
  }
  const bool none = !s.rules.aggregates && e.creations + e.growths + e.dissipations + e.shrinks > 0;
  const bool growth = !s.rules.joins && e.growths > 0;
  const bool left = !s.rules.leaves && e.dissipations + e.shrinks > 0;
  const bool shrink = s.rules.partners_only && e.shrinks > 0;
  if (none || growth || left || shrink)
    violated(s, "events counted that the rules rule out" + show());
}

// Solid to each other during the step: either one's blocked_by mask holds the other's signal.
bool solid(const CheckedState& s, std::size_t i, std::size_t j) {
  return solid_pair(s.commands[i].blocked_by, s.signals[i], s.commands[j].blocked_by, s.signals[j]);
}

}  // namespace

CheckedState checked_state(const Replicate& r) {
  return {r.spec(),
          r.rules(),
          r.index(),
          r.steps_done(),
          r.engine().positions(),
          r.engine().neighbours(),
          r.swarm(),
          r.aggregates(),
          r.events(),
          r.engine().sleeper_due_to_move(),
          r.commands(),
          r.signals()};
}

void check_sleep(const CheckedState& s) {
  if (!s.sleeper_due_to_move) return;
  violated(s, "agent " + std::to_string(*s.sleeper_due_to_move) +
                  " slept, but the step resolved in full moves it or changes what it counted");
}

void InvariantChecker::check(const CheckedState& state) {
  check_sizes(state);
  check_positions(state);
  check_agents(state);
  check_aggregates(state);
  check_sleep(state);
  if (continues(state)) {
    check_counts_grow(state);
    check_motion(state);
    check_contacts(state);
  }
  remember(state);
}

bool InvariantChecker::continues(const CheckedState& state) const {
  return step_ >= 0 && spec_ == &state.spec && replicate_ == state.replicate &&
         state.step == step_ + 1 && positions_.size() == state.positions.size();
}

void InvariantChecker::check_aggregates(const CheckedState& s) {
  const AggregateTracker& t = s.aggregates;
  const auto sizes = t.sizes();
  const auto label = t.aggregate_of();
  const auto size_of = t.size_of_agent();
  const auto count = static_cast<std::int32_t>(sizes.size());
  if (t.count() != count) {
    violated(s, "NOA is " + std::to_string(t.count()) + " but " + std::to_string(count) +
                    " aggregate sizes are listed");
  }
  members_.assign(sizes.size(), 0);
  int waiting = 0;
  for (std::size_t i = 0; i < s.swarm.size(); ++i) {
    if (s.swarm.state[i] == AgentState::Wait) ++waiting;
    const std::int32_t a = label[i];
    const std::int32_t size = a >= 0 && a < count ? sizes[a] : 0;
    const bool bad = a >= count || (a >= 0 && s.swarm.state[i] != AgentState::Wait);
    if (bad || size_of[i] != size) {
      violated(s, agent(s, i) + " is labelled with aggregate " + std::to_string(a) + " of " +
                      std::to_string(count) + ", size " + std::to_string(size_of[i]));
    }
    if (a >= 0) ++members_[a];
  }
  int largest = 0;
  for (std::int32_t a = 0; a < count; ++a) {
    const bool pair_only = s.rules.partners_only && sizes[a] != 2;
    if (sizes[a] < 2 || pair_only || members_[a] != sizes[a]) {
      violated(s, "aggregate " + std::to_string(a) + " has size " + std::to_string(sizes[a]) +
                      " and " + std::to_string(members_[a]) + " members");
    }
    largest = std::max(largest, static_cast<int>(sizes[a]));
  }
  if (t.largest() != largest) {
    violated(s, "the largest aggregate is reported as " + std::to_string(t.largest()) +
                    " agents, but is " + std::to_string(largest));
  }
  check_links(s);
  check_events(s, waiting);
}

void InvariantChecker::check_counts_grow(const CheckedState& s) const {
  const EventCounts& e = s.events;
  if (e.creations < events_.creations || e.growths < events_.growths ||
      e.dissipations < events_.dissipations || e.shrinks < events_.shrinks ||
      e.encounters < events_.encounters) {
    violated(s, "a cumulative event count decreased");
  }
}

void InvariantChecker::check_motion(const CheckedState& s) const {
  if (box2d(s.spec)) return;  // contacts and repulsion may push bodies faster than v
  const ArenaGeometry geometry = s.spec.arena.geometry();
  const double reach = s.spec.robots.speed * s.spec.engine.dt;
  const double slack = kRounding * (longest_side(s.spec) + reach);
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    const double moved = geometry.distance(positions_[i], s.positions[i]);
    // Waiting agents move only to close up their aggregate (docs/controllers.md, "Compaction").
    const double limit = s.swarm.state[i] == AgentState::Wait && !s.rules.compacts ? 0.0 : reach;
    if (moved > limit + slack) {
      violated(s, agent(s, i) + " moved " + format_number(moved) + " from " + point(positions_[i]) +
                      " to " + point(s.positions[i]) + " in one step; at most " +
                      format_number(limit) + " allowed");
    }
  }
}

void InvariantChecker::check_contacts(const CheckedState& s) const {
  if (s.commands.size() != s.swarm.size() || s.signals.size() != s.swarm.size())
    throw std::logic_error("check_contacts: the state lacks the step's commands or signals");
  const double r = s.spec.robots.radius;
  const double contact = 2.0 * r;
  const double tolerance = box2d(s.spec) ? r : kRounding * longest_side(s.spec);
  const ArenaGeometry geometry = s.spec.arena.geometry();
  for (std::size_t i = 0; i < s.swarm.size(); ++i) {
    for (const Neighbour& nb : s.neighbours.of(static_cast<AgentId>(i))) {
      if (nb.distance >= contact) break;  // nearest first
      const std::size_t j = nb.id;
      if (j < i || !solid(s, i, j)) continue;
      const double before = geometry.distance(positions_[i], positions_[j]);
      const double sunk = (contact - nb.distance) - std::max(0.0, contact - before);
      if (sunk <= tolerance) continue;
      violated(s, agent(s, i) + " and " + agent(s, j) + " are solid to each other but sank " +
                      format_number(sunk) + " into each other: centres " + format_number(before) +
                      " then " + format_number(nb.distance) + " apart, contact at " +
                      format_number(contact));
    }
  }
}

void InvariantChecker::remember(const CheckedState& state) {
  spec_ = &state.spec;
  replicate_ = state.replicate;
  step_ = state.step;
  positions_.assign(state.positions.begin(), state.positions.end());
  events_ = state.events;
}

void check_invariants(const Replicate& replicate) {
  thread_local InvariantChecker checker;
  thread_local const Replicate* last = nullptr;
  if (last != &replicate) checker.forget();
  last = &replicate;
  checker.check(checked_state(replicate));
}

}  // namespace swarmagg
