#include "engine/kinematic/guarded_motion.hpp"

#include <algorithm>
#include <bit>
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
// Loops over pairs or events whose agents' data lie at random ids request those data this
// many items ahead: enough to cover a miss to memory with the work of the items between.
constexpr std::uint32_t kPrefetchAhead = 16;
// Initial room in the buffers of one agent's neighbours: a packed body has about six, the
// pair reach holds a few more.
constexpr std::size_t kNeighboursRoom = 64;
// Runs of events this short are sorted by insertion.
constexpr std::size_t kSmallSort = 16;

// `when ? a : b` by bit masks: for choices that differ from one neighbour to the next,
// which the branch predictor cannot learn (GCC keeps a branch for a Vec2 ?:).
Vec2 choose(bool when, Vec2 a, Vec2 b) {
  const std::uint64_t take_a = 0 - static_cast<std::uint64_t>(when);
  auto pick = [&](double x, double y) {
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(x) & take_a) |
                                 (std::bit_cast<std::uint64_t>(y) & ~take_a));
  };
  return {pick(a.x, b.x), pick(a.y, b.y)};
}

// The offset from i to j of a pair that was `start_offset` at the step's start, once its ends
// have travelled: the agent at hand `travelled` (end j when `agent_is_j`), the other
// `other_travelled`.
Vec2 offset_now(Vec2 start_offset, bool agent_is_j, Vec2 travelled, Vec2 other_travelled) {
  return choose(agent_is_j, start_offset + travelled - other_travelled,
                start_offset + other_travelled - travelled);
}

}  // namespace

// Earliest event first; simultaneous events by their pair's agent ids (i, then j; a wall
// event as the pair (agent, no one)), then by kind, so the order never depends on how the
// heap or the pair list is arranged. Event times are never negative (nor -0.0): they start at
// 0 and add non-negative spans. The bits of such a double order like its value, so time and
// ids compare as one 128-bit number, without branches the predictor would have to guess.
// (Islands need no comparison here: see pop_event.)
bool GuardedMotion::earlier(const Event& a, const Event& b) {
  using Key = unsigned __int128;
  const Key key_a = Key{std::bit_cast<std::uint64_t>(a.time)} << 64 | a.ids;
  const Key key_b = Key{std::bit_cast<std::uint64_t>(b.time)} << 64 | b.ids;
  return (key_a < key_b) | ((key_a == key_b) & (a.kind < b.kind));
}

void GuardedMotion::push_event(const Event& event) {
  if (starting_) {
    start_events_.push_back(event);
    return;
  }
  heap_.push_back(event);
  sift_up(heap_.size() - 1, event);
}

// Moves `event` up from the free slot `hole` of the heap to where it belongs.
void GuardedMotion::sift_up(std::size_t hole, const Event& event) {
  while (hole > 0) {
    const std::size_t parent = (hole - 1) / 2;
    if (!earlier(event, heap_[parent])) break;
    heap_[hole] = heap_[parent];
    hole = parent;
  }
  heap_[hole] = event;
}

// Ordered by island, a counting sort by island (which keeps the order of the events within
// one) comes first, and each island's events are sorted by time in turn.
void GuardedMotion::sort_start_events() {
  const std::size_t count = start_events_.size();
  sorted_events_.resize(count);
  if (!by_island_) {
    sort_events_into(start_events_.data(), start_events_.data() + count, sorted_events_.data());
    start_events_.swap(sorted_events_);
    return;
  }
  island_begin_.assign(islands_ + 1, 0);
  for (const Event& event : start_events_) ++island_begin_[event.island + 1];
  for (std::uint32_t k = 0; k < islands_; ++k) island_begin_[k + 1] += island_begin_[k];
  for (const Event& event : start_events_) sorted_events_[island_begin_[event.island]++] = event;
  // island_begin_[k] is now where island k ends.
  std::size_t begin = 0;
  for (std::uint32_t k = 0; k < islands_; ++k) {
    const std::size_t end = island_begin_[k];
    sort_events_into(sorted_events_.data() + begin, sorted_events_.data() + end,
                     start_events_.data() + begin);
    begin = end;
  }
}

// A counting sort by time slot (a slot per event on average: the slot is monotone in time, so
// events in earlier slots come first), then each slot sorted by the full order: a few
// passes over the events and small sorts, where one comparison sort of all would guess
// wrong at about every other comparison. All the events at time 0 share the first slot,
// which a comparison sort takes when it is large.
void GuardedMotion::sort_events_into(const Event* first, const Event* last, Event* out) {
  const auto count = static_cast<std::size_t>(last - first);
  auto by_order = [](const Event& a, const Event& b) { return earlier(a, b); };
  auto insertion_sort = [](Event* begin, Event* end) {
    if (end - begin < 2) return;  // begin + 1 would point past an empty run's end
    for (Event* m = begin + 1; m < end; ++m) {
      const Event event = *m;
      Event* hole = m;
      for (; hole > begin && earlier(event, hole[-1]); --hole) *hole = hole[-1];
      *hole = event;
    }
  };
  if (count <= kSmallSort) {
    std::copy(first, last, out);
    insertion_sort(out, out + count);
    return;
  }
  const double per_time = static_cast<double>(count) / limits_.dt;
  auto slot = [&](const Event& event) {
    return std::min(count - 1, static_cast<std::size_t>(event.time * per_time));
  };
  slot_begin_.assign(count + 1, 0);
  for (const Event* event = first; event < last; ++event) ++slot_begin_[slot(*event) + 1];
  for (std::size_t k = 0; k < count; ++k) slot_begin_[k + 1] += slot_begin_[k];
  for (const Event* event = first; event < last; ++event) out[slot_begin_[slot(*event)]++] = *event;
  // slot_begin_[k] is now where slot k ends.
  std::size_t begin = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t end = slot_begin_[k];
    if (end - begin > kSmallSort) {
      std::sort(out + begin, out + end, by_order);
    } else {
      insertion_sort(out + begin, out + end);
    }
    begin = end;
  }
}

// Union-find, each island's root its lowest member. A parent is valid where stamped with this
// step's stamp; an agent without one is a root of its own.
std::uint32_t GuardedMotion::find_root(std::uint32_t agent) {
  if (island_stamp_[agent] != step_stamp_) {
    island_stamp_[agent] = step_stamp_;
    island_parent_[agent] = agent;
    return agent;
  }
  while (island_parent_[agent] != agent) {
    island_parent_[agent] = island_parent_[island_parent_[agent]];  // path halving
    agent = island_parent_[agent];
  }
  return agent;
}

// An agent commanded to stand never changes (it cannot halt or slide), so events reach from
// one agent to another only through pairs of two moving agents: those make the islands.
void GuardedMotion::unite_if_both_move(const CandidatePair& pair) {
  if (is_zero(commands_[pair.i].velocity) || is_zero(commands_[pair.j].velocity)) return;
  const std::uint32_t root_i = find_root(pair.i);
  const std::uint32_t root_j = find_root(pair.j);
  if (root_i < root_j) island_parent_[root_j] = root_i;
  if (root_j < root_i) island_parent_[root_i] = root_j;
}

// Islands are numbered as their first events come (the start events in the order of their
// pairs, which are listed by place).
std::uint32_t GuardedMotion::island_of(std::uint32_t agent) {
  const std::uint32_t root = find_root(agent);
  if (number_stamp_[root] != step_stamp_) {
    number_stamp_[root] = step_stamp_;
    island_number_[root] = islands_++;
  }
  return island_number_[root];
}

// Pops the earlier of the next start event and the heap's top. Ordered by island, the start
// events run island after island, and the heap holds only events of the island at hand (an
// event's changes schedule events of its own island): while the next start event belongs to
// a later island, the heap empties first. The heap is popped bottom-up: the hole left by the
// top walks down to a leaf along the earlier child (one branch-free comparison a level), and
// the last event is sifted up from there, which rarely takes more than a level or two.
GuardedMotion::Event GuardedMotion::pop_event() {
  if (next_start_ < start_events_.size() &&
      (heap_.empty() || (start_events_[next_start_].island == heap_.front().island &&
                         !earlier(heap_.front(), start_events_[next_start_])))) {
    // What checking and processing an event reads first, of both its agents, requested
    // a few events ahead (written out here: GCC drops calls to a function that only
    // prefetches, taking it for one without effects), with what a change of leg writes (a
    // store that misses holds up every later read of a stored value, spilled registers
    // included: at 10^6 agents that stall was most of rescheduling); the runs of incident
    // ends, found from incidence_begin_ requested earlier, at half that distance.
    if (next_start_ + kPrefetchAhead < start_events_.size()) {
      const Event& ahead = start_events_[next_start_ + kPrefetchAhead];
      for (const std::uint32_t agent : {ahead.i(), ahead.j()}) {
        if (agent == kNoOne) continue;
        __builtin_prefetch(&version_[agent]);
        __builtin_prefetch(&commands_[agent]);
        __builtin_prefetch(&signals_[agent]);
        __builtin_prefetch(&leg_stamp_[agent]);
        __builtin_prefetch(&leg_[agent], 1);
        __builtin_prefetch(&slides_[agent], 1);
        __builtin_prefetch(&walls_touched_[agent], 1);
        if (incidence_built_) __builtin_prefetch(&incidence_begin_[agent]);
      }
      if (incidence_built_) {
        const Event& nearer = start_events_[next_start_ + kPrefetchAhead / 2];
        for (const std::uint32_t agent : {nearer.i(), nearer.j()}) {
          if (agent != kNoOne) __builtin_prefetch(&incident_ends_[incidence_begin_[agent]]);
        }
      }
    }
    return start_events_[next_start_++];
  }
  const Event top = heap_.front();
  const Event last = heap_.back();
  heap_.pop_back();
  const std::size_t size = heap_.size();
  if (size == 0) return top;
  std::size_t hole = 0;
  std::size_t child = 2;
  for (; child < size; child = 2 * hole + 2) {
    child -= static_cast<std::size_t>(earlier(heap_[child - 1], heap_[child]));
    heap_[hole] = heap_[child];
    hole = child;
  }
  if (child == size) {  // a last lone child
    heap_[hole] = heap_[child - 1];
    hole = child - 1;
  }
  sift_up(hole, last);
  return top;
}

// A pair is solid when either side's blocked_by holds the other's signal, as Box2D's contact
// filter decides: a body cannot be solid to another that passes over it. (The controllers set
// both sides' bits, or the unblocked side stands; a user controller may set one side only.)
bool GuardedMotion::solid(std::uint32_t a, std::uint32_t b) const {
  return solid_pair(commands_[a].blocked_by, signals_[a], commands_[b].blocked_by, signals_[b]);
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
  if (is_zero(relative)) return;
  // Ordered by island, the event holds its moving agent until the islands are known (see
  // resolve): i unless i stands (then j moves, or the pair would have no event).
  const std::uint32_t island =
      !by_island_ ? 0 : (is_zero(commands_[pair.i].velocity) ? pair.j : pair.i);
  schedule_events(index, pair.offset, relative, 0.0, island);
}

void GuardedMotion::schedule_events(std::uint32_t index, Vec2 offset, Vec2 relative,
                                    double from_time, std::uint32_t island) {
  const CandidatePair& pair = pairs_[index];
  const std::uint64_t ids = std::uint64_t{pair.i} << 32 | pair.j;
  auto push = [&](double time, Kind kind) {
    push_event({time, ids, version_[pair.i], version_[pair.j], island, kind});
  };
  if (auto t =
          first_contact_time(offset, relative, limits_.detection_radius, from_time, limits_.dt)) {
    // pair.offset is the step's start offset. A pair that met last step was halted on the
    // radius, where rounding may leave it an ulp outside: one that starts on it (to 1e-12)
    // met already, and its next step inwards (as waiting members close up) is no new
    // encounter; one farther out is.
    const double met = limits_.detection_radius * (1.0 + 1e-12);
    push(*t, norm2(pair.offset) <= met * met ? Kind::PerceiveAgain : Kind::Perceive);
  }
  if (!solid(pair.i, pair.j)) return;
  const double contact = limits_.contact_distance;
  if (norm2(offset) <= contact * contact) {
    // Already touching: a body may move away or sideways, never further in.
    if (approaching(offset, relative)) push(from_time, Kind::Contact);
  } else if (auto t = first_contact_time(offset, relative, contact, from_time, limits_.dt)) {
    push(*t, Kind::Contact);
  }
}

// The first time from `from_time` at which the agent is at a wall moving into it.
void GuardedMotion::schedule_wall(std::uint32_t agent, double from_time, std::uint32_t island) {
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
  push_event({first, std::uint64_t{agent} << 32 | kNoOne, version_[agent], version_[agent], island,
              Kind::Wall});
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
    const CandidatePair& p = pairs_[pair];
    incident_ends_[--incidence_begin_[p.i]] = {2 * pair, p.j};
    incident_ends_[--incidence_begin_[p.j]] = {2 * pair + 1, p.i};
  }
  incidence_built_ = true;
}

// Reads the agent's pairs and where the other agent of each is at `time`. The other agents'
// data lie at random ids: all are requested before any is used, so that their cache misses
// overlap.
void GuardedMotion::gather_neighbours(std::uint32_t agent, double time) {
  const std::span<const Incidence> run = incident_ends(agent);
  // The buffers only grow: resizing them down and up would clear what is overwritten anyway.
  if (neighbours_.size() < run.size()) neighbours_.resize(2 * run.size());
  neighbour_count_ = run.size();
  for (std::size_t k = 0; k < run.size(); ++k) {
    const Incidence& incidence = run[k];
    __builtin_prefetch(&pairs_[incidence.end >> 1]);
    __builtin_prefetch(&leg_stamp_[incidence.other]);
    __builtin_prefetch(&leg_[incidence.other]);
    __builtin_prefetch(&commands_[incidence.other]);
    __builtin_prefetch(&signals_[incidence.other]);
    neighbours_[k].end = incidence.end;
    neighbours_[k].other = incidence.other;
  }
  // velocity_after and displacement_travelled, with every side read so that the choices
  // need no branch.
  for (Neighbour& n : neighbours()) {
    const bool is_bent = bent(n.other);
    const Leg& leg = leg_[n.other];
    const Vec2 commanded = commands_[n.other].velocity;
    const bool standing = is_zero(leg.velocity);
    const Vec2 on_leg =
        choose(standing, leg.origin, leg.origin + leg.velocity * (time - leg.start));
    n.velocity = choose(is_bent, leg.velocity, commanded);
    n.travelled = choose(is_bent, on_leg, commanded * time);
  }
}

// Schedules the agent's pairs anew from `time` on, when its new leg starts at `origin` with
// `velocity` (passed in registers, not read back from leg_: a read the store buffer cannot
// hand over, as GCC's wider reload of a value it spilled in halves, waits for every earlier
// store, and those of a newly bent agent miss the cache); pairs that keep their distance
// have no events. `gathered`: neighbours_ hold the agent's neighbours at `time` already.
//
// Ordered by island, all these events are the island's of the event being processed: the
// agent changes, so it moves (an agent commanded to stand never changes) and shares that
// event's island, and each of its pairs is in its island or has it as its moving end. (Looking
// the island up instead would miss the cache at every reschedule of a large swarm.)
void GuardedMotion::reschedule(std::uint32_t agent, double time, Vec2 origin, Vec2 velocity,
                               bool gathered) {
  ++version_[agent];
  const std::uint32_t island = event_island_;
  if (meets_walls(agent)) schedule_wall(agent, time, island);
  const Vec2 travelled = travelled_on({time, origin, velocity}, time);
  if (!gathered) gather_neighbours(agent, time);
  for (const Neighbour& n : neighbours()) {
    const CandidatePair& pair = pairs_[n.end >> 1];
    const bool agent_is_j = (n.end & 1) != 0;
    const Vec2 relative = choose(agent_is_j, velocity - n.velocity, n.velocity - velocity);
    if (is_zero(relative)) continue;
    const Vec2 offset = offset_now(pair.offset, agent_is_j, travelled, n.travelled);
    schedule_events(n.end >> 1, offset, relative, time, island);
  }
}

void GuardedMotion::change_leg(std::uint32_t agent, double time, Vec2 velocity, bool gathered) {
  if (!incidence_built_) build_incidence();
  const Vec2 origin = displacement_travelled(agent, time);
  if (!bent(agent)) {
    leg_stamp_[agent] = step_stamp_;
    slides_[agent] = 0;
    walls_touched_[agent] = 0;
    bent_agents_.push_back(agent);
  }
  leg_[agent] = {time, origin, velocity};
  reschedule(agent, time, origin, velocity, gathered);
}

// The agent stands from `time` on, until a contact it answers lets it slide (see
// halt_for_good); a halt at the step's end changes nothing (and keeps the events due then).
void GuardedMotion::halt(std::uint32_t agent, double time, bool gathered) {
  if (time >= limits_.dt) return;
  const Vec2 v = velocity_after(agent);
  if (is_zero(v)) return;  // standing already
  change_leg(agent, time, Vec2{}, gathered);
}

// Perceiving an agent it halts on, the agent stands for the rest of the step: no slide is
// left to it, so a body pressing into it later cannot start it again (as on the Box2D engine,
// where a halted body takes no command until the next step).
void GuardedMotion::halt_for_good(std::uint32_t agent, double time) {
  halt(agent, time);
  if (bent(agent)) slides_[agent] = kMaxSlides;
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
  const double touching = limits_.contact_distance * (1.0 + kTouchingSlack);
  const Vec2 travelled = displacement_travelled(agent, time);
  // Half the neighbours of a body in a packed aggregate touch it: every neighbour is
  // measured (a square root is cheaper than a mispredicted branch) and kept or not without
  // a branch.
  if (contacts_.size() < neighbour_count_) contacts_.resize(neighbours_.size());
  std::size_t touched = 0;
  for (const Neighbour& n : neighbours()) {
    const CandidatePair& pair = pairs_[n.end >> 1];
    const bool agent_is_j = (n.end & 1) != 0;
    const Vec2 from_i = offset_now(pair.offset, agent_is_j, travelled, n.travelled);
    const Vec2 towards = choose(agent_is_j, Vec2{} - from_i, from_i);
    const double distance = norm(towards);
    contacts_[touched] = {n.other, towards * (1.0 / distance)};
    const bool within = !(distance > touching) & !(distance <= 0.0);
    touched += static_cast<std::size_t>(within & solid(agent, n.other));
  }
  // A body touches a handful of others, with distinct ids: insertion sort.
  for (std::size_t k = 1; k < touched; ++k) {
    for (std::size_t m = k; m > 0 && contacts_[m].first < contacts_[m - 1].first; --m) {
      std::swap(contacts_[m], contacts_[m - 1]);
    }
  }
  for (std::size_t k = 0; k < touched; ++k) normals.push_back(contacts_[k].second);
}

// The agent touches a body solid to it or a wall, and one of them presses into the other.
// Sliding, it goes on with the part of its commanded velocity that everything it touches now
// lets through. When that is what it already does, the contact pressed into it, not it into
// the contact: it goes on unchanged (the other body answers for its own press; halting here
// let a jammed neighbour, pressing without moving, hold a body moving away for good). When
// that is nothing, slower than limits_.min_slide_speed, or it slid too often this step (or
// halted for good: halt_for_good spends its slides), it halts.
//
// An agent commanded to stand is never bent (it cannot halt, and free_motion of a zero
// velocity is zero, which is what it does), so nothing here changes it: a waiting agent
// pressed on by a moving neighbour returns at once.
void GuardedMotion::respond_to_contact(std::uint32_t agent, double time) {
  if (time >= limits_.dt) return;
  const Vec2 commanded = commands_[agent].velocity;
  if (is_zero(commanded)) return;
  if (!incidence_built_) build_incidence();
  normals_.clear();
  const std::uint8_t walls = touched_walls(agent, time, normals_);
  if (limits_.response == ContactResponse::Stop || (bent(agent) && slides_[agent] >= kMaxSlides)) {
    halt(agent, time);
  } else {
    gather_neighbours(agent, time);
    touched_bodies(agent, time, normals_);
    const Vec2 slide = free_motion(commanded, normals_);
    const Vec2 now = velocity_after(agent);
    // Only the agent's own leg changes from here on: the neighbours stay as gathered. When
    // the slide is what it already does, it goes on as it was.
    const bool changes = slide.x != now.x || slide.y != now.y;
    const double slowest = limits_.min_slide_speed;
    if (changes && (is_zero(slide) || norm2(slide) < slowest * slowest)) {
      halt(agent, time, true);
    } else if (changes) {
      change_leg(agent, time, slide, true);
      ++slides_[agent];
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
    island_parent_.assign(agents, 0u);
    island_stamp_.assign(agents, 0u);
    island_number_.assign(agents, 0u);
    number_stamp_.assign(agents, 0u);
    island_begin_.reserve(agents + 1);  // an island has at least one agent
    // Room for more neighbours than a packed body has, so that the buffers do not grow
    // during a run.
    neighbours_.resize(kNeighboursRoom);
    contacts_.resize(kNeighboursRoom);
    normals_.reserve(kNeighboursRoom);
    step_stamp_ = 0;
  }
  if (step_stamp_ == std::numeric_limits<std::uint32_t>::max()) {
    std::fill(leg_stamp_.begin(), leg_stamp_.end(), 0u);
    std::fill(island_stamp_.begin(), island_stamp_.end(), 0u);
    std::fill(number_stamp_.begin(), number_stamp_.end(), 0u);
    step_stamp_ = 0;
  }
  ++step_stamp_;
  bent_agents_.clear();
  met_agents_.clear();
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
  start_events_.clear();
  next_start_ = 0;
  // Each pair schedules at most two events at the start: room for twice the pairs up front
  // keeps the buffer from growing step by step as aggregates densify.
  if (start_events_.capacity() < 2 * pairs.size()) {
    start_events_.reserve(4 * pairs.size());
    sorted_events_.reserve(4 * pairs.size());
    slot_begin_.reserve(4 * pairs.size() + 1);
    heap_.reserve(4 * pairs.size());  // events scheduled after the start
  }
  by_island_ = order_ == EventOrder::ByIsland ||
               (order_ == EventOrder::Auto && commands.size() >= kIslandOrderFrom);
  islands_ = 0;
  starting_ = true;
  // The pairs are listed by place, their agents' data lie at random ids: they are requested
  // a few pairs ahead, so that the cache misses of several pairs overlap.
  const auto count = static_cast<std::uint32_t>(pairs.size());
  for (std::uint32_t k = 0; k < count; ++k) {
    if (k + kPrefetchAhead < count) {
      const CandidatePair& ahead = pairs_[k + kPrefetchAhead];
      __builtin_prefetch(&commands_[ahead.i]);
      __builtin_prefetch(&commands_[ahead.j]);
      __builtin_prefetch(&version_[ahead.i]);
      __builtin_prefetch(&version_[ahead.j]);
      if (by_island_) {
        __builtin_prefetch(&island_stamp_[ahead.i]);
        __builtin_prefetch(&island_stamp_[ahead.j]);
      }
    }
    if (by_island_) unite_if_both_move(pairs_[k]);
    schedule_pair_at_start(k);
  }
  if (limits_.walls) {
    for (std::uint32_t a = 0; a < commands.size(); ++a) {
      if (meets_walls(a)) schedule_wall(a, 0.0, by_island_ ? a : 0);
    }
  }
  starting_ = false;
  // Each start event's island is its moving agent's (held in the field until now), looked up
  // with the union-find's entries requested a few events ahead.
  if (by_island_) {
    const std::size_t events = start_events_.size();
    for (std::size_t k = 0; k < events; ++k) {
      if (k + kPrefetchAhead < events) {
        const std::uint32_t ahead = start_events_[k + kPrefetchAhead].island;
        __builtin_prefetch(&island_stamp_[ahead]);
        __builtin_prefetch(&island_parent_[ahead]);
      }
      start_events_[k].island = island_of(start_events_[k].island);
    }
  }
  sort_start_events();

  // An event is current while neither agent changed since it was scheduled; a change
  // schedules the pair anew with new versions, at most one perceive and one contact event,
  // so of several events with the same pair, kind and time at most one is current.
  std::uint64_t encounters = 0;
  while (next_start_ < start_events_.size() || !heap_.empty()) {
    const Event event = pop_event();
    event_island_ = event.island;
    const std::uint32_t i = event.i();
    if (event.kind == Kind::Wall) {
      if (event.version_i == version_[i]) respond_to_contact(i, event.time);
      continue;
    }
    const std::uint32_t j = event.j();
    if (event.version_i != version_[i] || event.version_j != version_[j]) continue;
    if (event.kind == Kind::Perceive || event.kind == Kind::PerceiveAgain) {
      encounters += event.kind == Kind::Perceive;
      met_agents_.push_back(i);
      met_agents_.push_back(j);
      const bool halt_i = halts_for(i, j);
      const bool halt_j = halts_for(j, i);
      if (halt_i) halt_for_good(i, event.time);
      if (halt_j) halt_for_good(j, event.time);
    } else {
      if (solid(i, j)) {
        respond_to_contact(i, event.time);
        respond_to_contact(j, event.time);
      }
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
