#include "engine/kinematic/guarded_motion.hpp"

#include <algorithm>
#include <limits>

#include "geometry/swept_contact.hpp"

namespace swarmagg {
namespace {

constexpr std::uint32_t kNoEnd = std::numeric_limits<std::uint32_t>::max();

}  // namespace

// Earliest event first; simultaneous events by their pair's agent ids (i, then j), then by
// kind, so the order never depends on how the heap or the pair list is arranged.
bool GuardedMotion::Later::operator()(const Event& a, const Event& b) const {
  if (a.time != b.time) return a.time > b.time;
  if (a.pair != b.pair) {
    const CandidatePair& p = pairs[a.pair];
    const CandidatePair& q = pairs[b.pair];
    if (p.i != q.i) return p.i > q.i;
    return p.j > q.j;
  }
  return a.kind > b.kind;
}

bool GuardedMotion::blocks(std::uint32_t mover, std::uint32_t other) const {
  return (commands_[mover].blocked_by & mask_of(signals_[other])) != 0;
}

bool GuardedMotion::halts_for(std::uint32_t mover, std::uint32_t other) const {
  return (commands_[mover].halt_on & mask_of(signals_[other])) != 0;
}

Vec2 GuardedMotion::displacement_travelled(std::uint32_t agent, double time) const {
  return commands_[agent].velocity * std::min(time, stop_time_[agent]);
}

Vec2 GuardedMotion::velocity_after(std::uint32_t agent, double time) const {
  return stop_time_[agent] > time ? commands_[agent].velocity : Vec2{};
}

void GuardedMotion::schedule_pair(std::uint32_t index, double from_time) {
  const CandidatePair& pair = pairs_[index];
  const Vec2 offset = pair.offset + displacement_travelled(pair.j, from_time) -
                      displacement_travelled(pair.i, from_time);
  const Vec2 relative = velocity_after(pair.j, from_time) - velocity_after(pair.i, from_time);
  // A pair that keeps its distance can neither meet nor press into contact (the general
  // tests below say the same, at a cost paid by every pair of a waiting aggregate).
  if (relative.x == 0.0 && relative.y == 0.0) return;
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

// Each pair is linked into the lists of both its agents. The lists come out in reverse
// pair order, which is harmless: the heap order is total, whatever the push order.
void GuardedMotion::build_incidence() {
  const auto ends = static_cast<std::uint32_t>(2 * pairs_.size());
  next_end_.resize(ends);
  ++stamp_;
  for (std::uint32_t end = 0; end < ends; ++end) {
    const CandidatePair& p = pairs_[end >> 1];
    const std::uint32_t agent = (end & 1) ? p.j : p.i;
    next_end_[end] = head_stamp_[agent] == stamp_ ? head_[agent] : kNoEnd;
    head_[agent] = end;
    head_stamp_[agent] = stamp_;
  }
  incidence_built_ = true;
}

void GuardedMotion::halt(std::uint32_t agent, double time) {
  if (stop_time_[agent] <= time) return;
  if (!incidence_built_) build_incidence();
  if (stop_time_[agent] == limits_.dt) halted_.push_back(agent);
  stop_time_[agent] = time;
  ++version_[agent];
  if (head_stamp_[agent] != stamp_) return;
  for (std::uint32_t end = head_[agent]; end != kNoEnd; end = next_end_[end]) {
    schedule_pair(end >> 1, time);
  }
}

// Stop times are dt except where the last step halted someone: only those are reset.
void GuardedMotion::reset(std::size_t agents, double dt) {
  if (stop_time_.size() != agents || limits_.dt != dt) {
    stop_time_.assign(agents, dt);
    version_.assign(agents, 0u);
    head_.assign(agents, 0u);
    head_stamp_.assign(agents, 0u);
    stamp_ = 0;
    // Every agent halts at most once a step: room for all, so that a swarm whose halts
    // keep growing (waiting agents pressing into packed aggregates) never reallocates.
    halted_.reserve(agents);
  } else {
    for (const std::uint32_t agent : halted_) stop_time_[agent] = dt;
  }
  halted_.clear();
}

std::uint64_t GuardedMotion::resolve(std::span<const CandidatePair> pairs,
                                     std::span<const MotionCommand> commands,
                                     std::span<const Signal> signals, const MotionLimits& limits) {
  reset(commands.size(), limits.dt);
  pairs_ = pairs;
  commands_ = commands;
  signals_ = signals;
  limits_ = limits;
  incidence_built_ = false;
  if (stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(head_stamp_.begin(), head_stamp_.end(), 0u);
    stamp_ = 0;
  }
  heap_.clear();
  // Each pair schedules at most two events at the start and two more per halt of either
  // agent; room for twice the pairs up front keeps the heap from growing step by step as
  // aggregates densify.
  if (heap_.capacity() < 2 * pairs.size()) heap_.reserve(4 * pairs.size());
  for (std::uint32_t k = 0; k < pairs.size(); ++k) schedule_pair(k, 0.0);

  std::uint64_t encounters = 0;
  const Later later{pairs_.data()};
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
    const Event event = heap_.back();
    heap_.pop_back();
    const CandidatePair& pair = pairs_[event.pair];
    if (event.version_i != version_[pair.i] || event.version_j != version_[pair.j]) continue;
    if (event.kind == Kind::Perceive) {
      ++encounters;
      const bool halt_i = halts_for(pair.i, pair.j);
      const bool halt_j = halts_for(pair.j, pair.i);
      if (halt_i) halt(pair.i, event.time);
      if (halt_j) halt(pair.j, event.time);
    } else {
      const bool halt_i = blocks(pair.i, pair.j);
      const bool halt_j = blocks(pair.j, pair.i);
      if (halt_i) halt(pair.i, event.time);
      if (halt_j) halt(pair.j, event.time);
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
