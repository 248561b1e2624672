#include "engine/kinematic/guarded_motion.hpp"

#include <algorithm>
#include <limits>

#include "geometry/free_motion.hpp"
#include "geometry/swept_contact.hpp"

namespace swarmagg {
namespace {

// A wall event's second agent: no one, ordered after every agent id.
constexpr std::uint32_t kNoOne = std::numeric_limits<std::uint32_t>::max();
// Bodies and walls within this fraction of contact count as touching when a body slides:
// contact times are roots of quadratics, exact up to rounding.
constexpr double kTouchingSlack = 1e-9;
// Relative margin on a squared distance far beyond rounding (a few 1e-16).
constexpr double kClearlyApart = 1e-12;

}  // namespace

// Earliest event first; simultaneous events by their pair's agent ids (i, then j; a wall
// event as the pair (agent, no one)), then by kind, so the order never depends on how the
// heap or the pair list is arranged.
bool GuardedMotion::Later::operator()(const Event& a, const Event& b) const {
  if (a.time != b.time) return a.time > b.time;
  const bool wall_a = a.kind == Kind::Wall, wall_b = b.kind == Kind::Wall;
  if (a.pair != b.pair || wall_a != wall_b) {
    const std::uint32_t ai = wall_a ? a.pair : pairs[a.pair].i;
    const std::uint32_t bi = wall_b ? b.pair : pairs[b.pair].i;
    if (ai != bi) return ai > bi;
    const std::uint32_t aj = wall_a ? kNoOne : pairs[a.pair].j;
    const std::uint32_t bj = wall_b ? kNoOne : pairs[b.pair].j;
    return aj > bj;
  }
  return a.kind > b.kind;
}

bool GuardedMotion::blocks(std::uint32_t mover, std::uint32_t other) const {
  return (commands_[mover].blocked_by & mask_of(signals_[other])) != 0;
}

bool GuardedMotion::halts_for(std::uint32_t mover, std::uint32_t other) const {
  return (commands_[mover].halt_on & mask_of(signals_[other])) != 0;
}

bool GuardedMotion::meets_walls(std::uint32_t agent) const {
  return limits_.walls && commands_[agent].blocked_by != 0;
}

// At the step's start every agent has its commanded velocity and no displacement yet, so
// the pair's offset is the one it was found with.
void GuardedMotion::schedule_pair_at_start(std::uint32_t index) {
  const CandidatePair& pair = pairs_[index];
  const Vec2 relative = commands_[pair.j].velocity - commands_[pair.i].velocity;
  // A pair that keeps its distance can neither meet nor press into contact (the general
  // tests say the same, at a cost paid by every pair of a waiting aggregate).
  if (relative.x == 0.0 && relative.y == 0.0) return;
  schedule_events(index, pair.offset, relative, 0.0);
}

void GuardedMotion::schedule_events(std::uint32_t index, Vec2 offset, Vec2 relative,
                                    double from_time) {
  const CandidatePair& pair = pairs_[index];
  auto push = [&](double time, Kind kind) {
    heap_.push_back({time, index, kind, version_[pair.i], version_[pair.j]});
    std::push_heap(heap_.begin(), heap_.end(), Later{pairs_.data()});
  };
  if (auto t =
          first_contact_time(offset, relative, limits_.detection_radius, from_time, limits_.dt)) {
    push(*t, Kind::Perceive);
  }
  if (!blocks(pair.i, pair.j) && !blocks(pair.j, pair.i)) return;
  const double contact = limits_.contact_distance;
  if (norm2(offset) <= contact * contact) {
    // Already touching: a body may move away or sideways, never further in.
    if (approaching(offset, relative)) push(from_time, Kind::Contact);
  } else if (auto t = first_contact_time(offset, relative, contact, from_time, limits_.dt)) {
    push(*t, Kind::Contact);
  }
}

// The first time from `from_time` at which the agent is at a wall moving into it.
void GuardedMotion::schedule_wall(std::uint32_t agent, double from_time) {
  const Vec2 at = positions_[agent] + displacement_travelled(agent, from_time);
  const Vec2 v = velocity_after(agent);
  double first = std::numeric_limits<double>::infinity();
  auto axis = [&](double x, double speed, double low, double high) {
    if (speed < 0.0) first = std::min(first, from_time + std::max(0.0, (low - x) / speed));
    if (speed > 0.0) first = std::min(first, from_time + std::max(0.0, (high - x) / speed));
  };
  axis(at.x, v.x, limits_.bounds.low.x, limits_.bounds.high.x);
  axis(at.y, v.y, limits_.bounds.low.y, limits_.bounds.high.y);
  if (first > limits_.dt) return;
  heap_.push_back({first, agent, Kind::Wall, version_[agent], version_[agent]});
  std::push_heap(heap_.begin(), heap_.end(), Later{pairs_.data()});
}

// A counting sort of the pair ends by agent: each agent's count lands in its own slot, the
// inclusive prefix sum turns it into the agent's end, and placing the ends by decrementing
// it leaves the agent's start. The runs come out in reverse pair order, which is harmless:
// the heap order is total, whatever the push order, and contacts are sorted by id.
void GuardedMotion::build_incidence() {
  const std::size_t agents = commands_.size();
  incidence_begin_.assign(agents + 1, 0u);
  for (const CandidatePair& p : pairs_) {
    ++incidence_begin_[p.i];
    ++incidence_begin_[p.j];
  }
  std::uint32_t total = 0;
  for (std::size_t a = 0; a <= agents; ++a) {
    total += incidence_begin_[a];
    incidence_begin_[a] = total;
  }
  incident_ends_.resize(total);
  for (auto pair = static_cast<std::uint32_t>(pairs_.size()); pair-- > 0;) {
    incident_ends_[--incidence_begin_[pairs_[pair].i]] = 2 * pair;
    incident_ends_[--incidence_begin_[pairs_[pair].j]] = 2 * pair + 1;
  }
  incidence_built_ = true;
}

// Schedules the agent's pairs anew from `time` on (its own velocity and displacement looked
// up once); pairs that keep their distance have no events.
void GuardedMotion::reschedule(std::uint32_t agent, double time) {
  ++version_[agent];
  if (meets_walls(agent)) schedule_wall(agent, time);
  const Vec2 velocity = velocity_after(agent);
  const Vec2 travelled = displacement_travelled(agent, time);
  for (const std::uint32_t end : incident_ends(agent)) {
    const CandidatePair& pair = pairs_[end >> 1];
    const bool agent_is_j = (end & 1) != 0;
    const std::uint32_t other = agent_is_j ? pair.i : pair.j;
    const Vec2 other_velocity = velocity_after(other);
    const Vec2 relative = agent_is_j ? velocity - other_velocity : other_velocity - velocity;
    if (relative.x == 0.0 && relative.y == 0.0) continue;
    const Vec2 other_travelled = displacement_travelled(other, time);
    const Vec2 offset = agent_is_j ? pair.offset + travelled - other_travelled
                                   : pair.offset + other_travelled - travelled;
    schedule_events(end >> 1, offset, relative, time);
  }
}

void GuardedMotion::change_leg(std::uint32_t agent, double time, Vec2 velocity) {
  if (!incidence_built_) build_incidence();
  const Vec2 origin = displacement_travelled(agent, time);
  if (!bent(agent)) {
    leg_stamp_[agent] = step_stamp_;
    slides_[agent] = 0;
    walls_touched_[agent] = 0;
    bent_agents_.push_back(agent);
  }
  leg_[agent] = {time, origin, velocity};
  reschedule(agent, time);
}

// An agent halted once stands for the rest of the step; a halt at the step's end changes
// nothing (and keeps the events due then).
void GuardedMotion::halt(std::uint32_t agent, double time) {
  if (time >= limits_.dt) return;
  const Vec2 v = velocity_after(agent);
  if (v.x == 0.0 && v.y == 0.0) return;  // standing already
  change_leg(agent, time, Vec2{});
}

// The walls the agent touches at `time`, as WallContact bits, with their normals appended.
std::uint8_t GuardedMotion::touched_walls(std::uint32_t agent, double time,
                                          std::vector<Vec2>& normals) const {
  if (!meets_walls(agent)) return 0;
  const Vec2 at = positions_[agent] + displacement_travelled(agent, time);
  const double slack = kTouchingSlack * limits_.contact_distance;
  const WallBounds& b = limits_.bounds;
  std::uint8_t walls = 0;
  auto touch = [&](bool touching, Vec2 normal, WallContact bit) {
    if (!touching) return;
    normals.push_back(normal);
    walls |= bit;
  };
  touch(at.x <= b.low.x + slack, {-1.0, 0.0}, WallX);
  touch(at.x >= b.high.x - slack, {1.0, 0.0}, WallX);
  touch(at.y <= b.low.y + slack, {0.0, -1.0}, WallY);
  touch(at.y >= b.high.y - slack, {0.0, 1.0}, WallY);
  return walls;
}

// The unit normals towards the bodies solid to the agent that it touches at `time`, in the
// order of their ids: ties between equally long slides are broken by that order, so the
// result does not depend on how the pairs are listed.
void GuardedMotion::touched_bodies(std::uint32_t agent, double time, std::vector<Vec2>& normals) {
  contacts_.clear();
  const double touching = limits_.contact_distance * (1.0 + kTouchingSlack);
  // Squared distances above this have a square root above `touching` whatever the rounding:
  // bodies clearly apart are passed over without one.
  const double apart2 = touching * touching * (1.0 + kClearlyApart);
  const Vec2 travelled = displacement_travelled(agent, time);
  for (const std::uint32_t end : incident_ends(agent)) {
    const CandidatePair& pair = pairs_[end >> 1];
    const bool agent_is_j = (end & 1) != 0;
    const std::uint32_t other = agent_is_j ? pair.i : pair.j;
    if (!blocks(agent, other)) continue;
    const Vec2 other_travelled = displacement_travelled(other, time);
    const Vec2 from_i = agent_is_j ? pair.offset + travelled - other_travelled
                                   : pair.offset + other_travelled - travelled;
    const Vec2 towards = agent_is_j ? Vec2{} - from_i : from_i;
    if (norm2(towards) > apart2) continue;
    const double distance = norm(towards);
    if (distance > touching || distance <= 0.0) continue;
    contacts_.push_back({other, towards * (1.0 / distance)});
  }
  // A body touches a handful of others, with distinct ids: insertion sort.
  for (std::size_t k = 1; k < contacts_.size(); ++k) {
    for (std::size_t m = k; m > 0 && contacts_[m].first < contacts_[m - 1].first; --m) {
      std::swap(contacts_[m], contacts_[m - 1]);
    }
  }
  for (const auto& contact : contacts_) normals.push_back(contact.second);
}

// The agent touches a body solid to it or a wall and presses into it. Sliding, it goes on
// with the part of its commanded velocity that everything it touches now lets through; when
// that is nothing, or what it already does (the contact presses into it, not it into the
// contact), or it slid too often this step, it halts.
void GuardedMotion::respond_to_contact(std::uint32_t agent, double time) {
  if (time >= limits_.dt) return;
  if (!incidence_built_) build_incidence();
  normals_.clear();
  const std::uint8_t walls = touched_walls(agent, time, normals_);
  if (limits_.response == ContactResponse::Stop || (bent(agent) && slides_[agent] >= kMaxSlides)) {
    halt(agent, time);
  } else {
    touched_bodies(agent, time, normals_);
    const Vec2 slide = free_motion(commands_[agent].velocity, normals_);
    const Vec2 now = velocity_after(agent);
    if (slide.x == now.x && slide.y == now.y) {
      halt(agent, time);
    } else {
      change_leg(agent, time, slide);
      if (slide.x != 0.0 || slide.y != 0.0) ++slides_[agent];
    }
  }
  if (bent(agent)) walls_touched_[agent] |= walls;
}

// Legs are valid only where stamped with this step's stamp: nothing is reset per agent.
void GuardedMotion::reset(std::size_t agents) {
  if (leg_.size() != agents) {
    leg_.assign(agents, Leg{});
    leg_stamp_.assign(agents, 0u);
    slides_.assign(agents, 0);
    walls_touched_.assign(agents, 0);
    version_.assign(agents, 0u);
    step_stamp_ = 0;
  }
  if (step_stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(leg_stamp_.begin(), leg_stamp_.end(), 0u);
    step_stamp_ = 0;
  }
  ++step_stamp_;
  bent_agents_.clear();
}

std::uint64_t GuardedMotion::resolve(std::span<const CandidatePair> pairs,
                                     std::span<const MotionCommand> commands,
                                     std::span<const Signal> signals, const MotionLimits& limits,
                                     std::span<const Vec2> positions) {
  reset(commands.size());
  pairs_ = pairs;
  commands_ = commands;
  signals_ = signals;
  positions_ = positions;
  limits_ = limits;
  incidence_built_ = false;
  heap_.clear();
  // Each pair schedules at most two events at the start and two more per change of either
  // agent; room for twice the pairs up front keeps the heap from growing step by step as
  // aggregates densify.
  if (heap_.capacity() < 2 * pairs.size()) heap_.reserve(4 * pairs.size());
  for (std::uint32_t k = 0; k < pairs.size(); ++k) schedule_pair_at_start(k);
  if (limits_.walls) {
    for (std::uint32_t a = 0; a < commands.size(); ++a) {
      if (meets_walls(a)) schedule_wall(a, 0.0);
    }
  }

  std::uint64_t encounters = 0;
  const Later later{pairs_.data()};
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Event event = heap_.back();
    heap_.pop_back();
    if (event.kind == Kind::Wall) {
      if (event.version_i == version_[event.pair]) respond_to_contact(event.pair, event.time);
      continue;
    }
    const CandidatePair& pair = pairs_[event.pair];
    if (event.version_i != version_[pair.i] || event.version_j != version_[pair.j]) continue;
    if (event.kind == Kind::Perceive) {
      ++encounters;
      const bool halt_i = halts_for(pair.i, pair.j);
      const bool halt_j = halts_for(pair.j, pair.i);
      if (halt_i) halt(pair.i, event.time);
      if (halt_j) halt(pair.j, event.time);
    } else {
      const bool blocked_i = blocks(pair.i, pair.j);
      const bool blocked_j = blocks(pair.j, pair.i);
      if (blocked_i) respond_to_contact(pair.i, event.time);
      if (blocked_j) respond_to_contact(pair.j, event.time);
    }
  }
  return encounters;
}

std::uint64_t GuardedMotion::count_encounters(std::span<const CandidatePair> pairs,
                                              std::span<const MotionCommand> commands,
                                              const MotionLimits& limits) {
  std::uint64_t encounters = 0;
  for (const CandidatePair& pair : pairs) {
    const Vec2 relative = commands[pair.j].velocity - commands[pair.i].velocity;
    if (first_contact_time(pair.offset, relative, limits.detection_radius, 0.0, limits.dt)) {
      ++encounters;
    }
  }
  return encounters;
}

}  // namespace swarmagg
