#include "engine/kinematic/guarded_motion.hpp"

#include <algorithm>

#include "geometry/swept_contact.hpp"

namespace swarmagg {
namespace {

// Earliest event first; ties broken by pair and kind so the order never depends on how
// the heap happens to be arranged.
struct Later {
  template <typename E>
  bool operator()(const E& a, const E& b) const {
    if (a.time != b.time) return a.time > b.time;
    if (a.pair != b.pair) return a.pair > b.pair;
    return a.kind > b.kind;
  }
};

}  // namespace

bool GuardedMotion::blocks(std::uint32_t mover, std::uint32_t other) const {
  return (commands_[mover].blocked_by & mask_of(signals_[other])) != 0;
}

bool GuardedMotion::halts_for(std::uint32_t mover, std::uint32_t other) const {
  return (commands_[mover].halt_on & mask_of(signals_[other])) != 0;
}

Vec2 GuardedMotion::displacement_travelled(std::uint32_t agent, double time) const {
  return commands_[agent].velocity * std::min(time, (*stop_time_)[agent]);
}

Vec2 GuardedMotion::velocity_after(std::uint32_t agent, double time) const {
  return (*stop_time_)[agent] > time ? commands_[agent].velocity : Vec2{};
}

void GuardedMotion::schedule_pair(std::uint32_t index, double from_time) {
  const CandidatePair& pair = pairs_[index];
  const Vec2 offset = pair.offset + displacement_travelled(pair.j, from_time) -
                      displacement_travelled(pair.i, from_time);
  const Vec2 relative = velocity_after(pair.j, from_time) - velocity_after(pair.i, from_time);
  auto push = [&](double time, Kind kind) {
    heap_.push_back({time, index, kind, version_[pair.i], version_[pair.j]});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  };
  if (auto t = first_contact_time(offset, relative, limits_.detection_radius, from_time,
                                  limits_.dt)) {
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

void GuardedMotion::build_incidence() {
  const std::size_t n = version_.size();
  incidence_start_.assign(n + 1, 0);
  for (const CandidatePair& p : pairs_) {
    ++incidence_start_[p.i + 1];
    ++incidence_start_[p.j + 1];
  }
  for (std::size_t a = 1; a <= n; ++a) incidence_start_[a] += incidence_start_[a - 1];
  incidence_.resize(incidence_start_[n]);
  incidence_cursor_.assign(incidence_start_.begin(), incidence_start_.end() - 1);
  for (std::uint32_t k = 0; k < pairs_.size(); ++k) {
    incidence_[incidence_cursor_[pairs_[k].i]++] = k;
    incidence_[incidence_cursor_[pairs_[k].j]++] = k;
  }
  incidence_built_ = true;
}

void GuardedMotion::halt(std::uint32_t agent, double time) {
  if ((*stop_time_)[agent] <= time) return;
  if (!incidence_built_) build_incidence();
  (*stop_time_)[agent] = time;
  ++version_[agent];
  for (std::uint32_t k = incidence_start_[agent]; k < incidence_start_[agent + 1]; ++k) {
    schedule_pair(incidence_[k], time);
  }
}

std::uint64_t GuardedMotion::resolve(std::span<const CandidatePair> pairs,
                                     std::span<const MotionCommand> commands,
                                     std::span<const Signal> signals, const MotionLimits& limits,
                                     std::vector<double>& stop_time) {
  pairs_ = pairs;
  commands_ = commands;
  signals_ = signals;
  limits_ = limits;
  stop_time_ = &stop_time;
  stop_time.assign(commands.size(), limits.dt);
  version_.assign(commands.size(), 0u);
  incidence_built_ = false;
  heap_.clear();
  for (std::uint32_t k = 0; k < pairs.size(); ++k) schedule_pair(k, 0.0);

  std::uint64_t encounters = 0;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
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

}  // namespace swarmagg
