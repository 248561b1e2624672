#pragma once
// Resolves one kinematic step exactly. Agents move with constant commanded velocities; the
// pair events of the step (centres reaching the detection radius s, bodies reaching contact
// at 2r) and, between walls, bodies reaching a wall are processed in time order (island by
// island, see EventOrder). An agent halts at the instant an event its command halts on fires
// (halt_on), for the rest of the step. At a contact with a body solid to it (blocked_by) or a
// wall it slides (ContactResponse::Slide): it goes on with the part of its commanded velocity
// that all the bodies and walls it touches let through (free_motion), at most kMaxSlides
// times a step and no slower than MotionLimits::min_slide_speed, then halts; or it halts there
// (ContactResponse::Stop). A contact that presses into a body moving away from it changes
// nothing for that body. After each change its later events are recomputed from its new
// trajectory. Every first contact within s is counted as an encounter. When no command guards
// its move, nothing can halt and the encounters are simply counted.
#include <cstdint>
#include <span>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/motion_command.hpp"
#include "core/agent_array.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

// Two agents that may meet during the step: i < j, `offset` from i to j at the step start.
// Simultaneous events are processed in the order of the pairs (i, j), whatever order the
// pairs are listed in.
struct CandidatePair {
  std::uint32_t i = 0;
  std::uint32_t j = 0;
  Vec2 offset;
};

// Walls hold body centres within [low, high] on both axes.
struct WallBounds {
  Vec2 low;
  Vec2 high;
};

struct MotionLimits {
  double detection_radius = 4.0;  // s
  double contact_distance = 2.0;  // 2r
  double dt = 0.1;
  ContactResponse response = ContactResponse::Slide;
  // Between walls, bodies solid to something (blocked_by) meet the walls as contacts; the
  // others (point particles passing over everything) are reflected by the engine.
  bool walls = false;
  WallBounds bounds;
  // A slide slower than this halts instead. A body pulled nearly head-on into a contact would
  // otherwise slide ever slower towards where the pull lies along the normal, never quite
  // coming to rest (a closing-up member does so for thousands of steps).
  double min_slide_speed = 0.0;
  // A step's move that events changed (a halt, a slide) and that is shorter than this
  // (squared) is dropped: the agent stays put. Such a move, far below anything a world asks
  // for, comes from an event a hair into the step; rounded to the grid of doubles it becomes
  // one ulp along an axis, which can point into a body the agent touches, and the agent then
  // sinks by an ulp a step and keeps its aggregate awake for ever. A move as commanded is
  // never dropped.
  double unresolved_move2 = 0.0;
};

// Bits of wall_contacts(): the walls an agent touched during the step.
enum WallContact : std::uint8_t { WallX = 1, WallY = 2 };

// The order in which a step's events are processed. Events of different islands never affect
// each other, so every order that keeps each island's events in time order gives the same
// step, bit for bit (only the lists bent_agents() and met_agents() come in another order;
// their users take them as sets). An island is a connected component of the candidate pairs of two
// moving agents: an agent commanded to stand never changes, so it passes nothing on; an event
// between a moving and a standing agent belongs to the moving one's island.
//  - ByTime: all events in one time order (cheapest bookkeeping);
//  - ByIsland: island after island, in the order of their first events (those at the step's
//    start, in the order of their pairs, which are listed by place; islands of wall events
//    alone come last), each in time order:
//    consecutive events then touch nearby agents, whose data stay in cache, where one time
//    order over a large swarm jumps across the arena at every event;
//  - Auto: ByIsland from kIslandOrderFrom agents, where the per-agent arrays outgrow the cache.
enum class EventOrder : std::uint8_t { Auto, ByTime, ByIsland };

class GuardedMotion {
 public:
  // A body meets few contacts within one step: it slides at most this often, then halts.
  static constexpr int kMaxSlides = 4;
  // Agents from which EventOrder::Auto orders by island: where the per-agent data the events
  // read (legs, commands, versions, incidence: about 100 bytes an agent) outgrow a 32 MiB
  // L3 cache. Below, labelling the islands costs more than it saves.
  static constexpr std::size_t kIslandOrderFrom = std::size_t{1} << 18;

  // For tests and benchmarks; the step is the same in every order.
  void set_event_order(EventOrder order) { order_ = order; }

  // Resolves the step for agents that guard their moves (some command has halt_on or
  // blocked_by bits) and returns the number of encounters; displacement() then gives how
  // far each agent moved. `positions` (the step's start) are needed only between walls.
  std::uint64_t resolve(std::span<const CandidatePair> pairs,
                        std::span<const MotionCommand> commands, std::span<const Signal> signals,
                        const MotionLimits& limits, std::span<const Vec2> positions = {});
  // The displacement of `agent` over the step resolved last.
  Vec2 displacement(std::uint32_t agent) const {
    if (!bent(agent)) return commands_[agent].velocity * limits_.dt;
    const Vec2 moved = travelled_on(leg_[agent], limits_.dt);
    return norm2(moved) < limits_.unresolved_move2 ? Vec2{} : moved;
  }
  // Requests what displacement(agent) reads into the cache: a loop over the bent agents
  // reads their legs at scattered ids, and asking a few agents ahead overlaps those misses.
  void prefetch_displacement(std::uint32_t agent) const {
    __builtin_prefetch(&leg_stamp_[agent]);
    __builtin_prefetch(&leg_[agent]);
    __builtin_prefetch(&leg_[agent].velocity.y);  // a leg may straddle two cache lines
  }
  // The agents whose motion changed during the step resolved last (each once): all others
  // moved with their commanded velocity for the whole step.
  std::span<const std::uint32_t> bent_agents() const { return bent_agents_; }
  // The agents of the encounters counted in the step resolved last (each pair's two, perhaps
  // repeated).
  std::span<const std::uint32_t> met_agents() const { return met_agents_; }
  // The walls `agent` touched during the step resolved last (WallContact bits).
  std::uint8_t wall_contacts(std::uint32_t agent) const {
    return leg_stamp_[agent] == step_stamp_ ? walls_touched_[agent] : 0;
  }

  // The encounters of a step in which no agent halts: every agent moves the whole step.
  static std::uint64_t count_encounters(std::span<const CandidatePair> pairs,
                                        std::span<const MotionCommand> commands,
                                        const MotionLimits& limits);

 private:
  // PerceiveAgain: a pair within the sensing radius when the step began that leaves it and comes
  // back within the step (by a hair, as waiting members close up): the agents meet as at a
  // Perceive, but it is no new encounter. It orders between Perceive and Contact, so every
  // order among the other kinds is as it was (one pair has one current perceive event).
  enum class Kind : std::uint8_t { Perceive, PerceiveAgain, Contact, Wall };
  // An event carries the ids it is ordered by and checked against, so that popping one reads
  // neither its pair nor (for a stale one) anything but the two versions.
  struct Event {
    double time;
    std::uint64_t ids;  // (i << 32) | j; for a Wall event (agent << 32) | no one
    std::uint32_t version_i;
    std::uint32_t version_j;
    std::uint32_t island;  // 0 for all unless ordered by island (see schedule_events)
    Kind kind;
    std::uint32_t i() const { return static_cast<std::uint32_t>(ids >> 32); }
    std::uint32_t j() const { return static_cast<std::uint32_t>(ids); }
  };
  // An agent's motion after its last change within the step: from `start` on it is at
  // `origin` (displacement from its step start) plus velocity * (t - start).
  struct Leg {
    double start;
    Vec2 origin;
    Vec2 velocity;
  };

  void reset(std::size_t agents);
  // The events of the step, earliest first (island after island when ordered by island).
  // Those scheduled at the step's start (most of them) are sorted once and read in order;
  // those scheduled later go to a binary min-heap, and each pop takes the earlier of the two
  // heads. A heap of all events would be walked
  // from top to bottom at every pop, which at a million agents misses the cache at every
  // lower level. The order is total up to events of the same pair, kind and time, of which
  // at most one is current (see resolve), so which of those pops first changes nothing.
  static bool earlier(const Event& a, const Event& b);
  void push_event(const Event& event);
  void sift_up(std::size_t hole, const Event& event);
  Event pop_event();
  void sort_start_events();
  // Sorts the events [first, last) by earlier() into `out` (not overlapping them).
  void sort_events_into(const Event* first, const Event* last, Event* out);
  std::uint32_t find_root(std::uint32_t agent);
  void unite_if_both_move(const CandidatePair& pair);
  std::uint32_t island_of(std::uint32_t agent);
  void schedule_pair_at_start(std::uint32_t pair);
  // Pushes the pair's perceive and contact events from `from_time` on, given its offset and
  // relative velocity then, in `island` (at the step's start, when the islands are still
  // being found, the event's moving agent: the start events get their islands once all are
  // scheduled; 0 for all when ordered by time).
  void schedule_events(std::uint32_t pair, Vec2 offset, Vec2 relative, double from_time,
                       std::uint32_t island);
  void schedule_wall(std::uint32_t agent, double from_time, std::uint32_t island);
  void gather_neighbours(std::uint32_t agent, double time);
  void reschedule(std::uint32_t agent, double time, Vec2 origin, Vec2 velocity, bool gathered);
  void change_leg(std::uint32_t agent, double time, Vec2 velocity, bool gathered);
  void halt(std::uint32_t agent, double time, bool gathered = false);
  void halt_for_good(std::uint32_t agent, double time);
  void respond_to_contact(std::uint32_t agent, double time);
  std::uint8_t touched_walls(std::uint32_t agent, double time, std::vector<Vec2>& normals) const;
  // Of the neighbours gathered at `time`.
  void touched_bodies(std::uint32_t agent, double time, std::vector<Vec2>& normals);
  void build_incidence();
  // A pair end (2 * pair + end, end 1 for j) with the pair's other agent, so that the other's
  // data can be requested without waiting for the pair to be read.
  struct Incidence {
    std::uint32_t end;
    std::uint32_t other;
  };
  std::span<const Incidence> incident_ends(std::uint32_t agent) const {
    return {incident_ends_.data() + incidence_begin_[agent],
            incident_ends_.data() + incidence_begin_[agent + 1]};
  }
  bool bent(std::uint32_t agent) const { return leg_stamp_[agent] == step_stamp_; }
  bool solid(std::uint32_t a, std::uint32_t b) const;
  bool halts_for(std::uint32_t mover, std::uint32_t other) const;
  bool meets_walls(std::uint32_t agent) const;
  // Written so that an agent that moved straight or halted once gets exactly the bits of
  // velocity * min(time, stop time): ContactResponse::Stop reproduces the halting engine.
  Vec2 displacement_travelled(std::uint32_t agent, double time) const {
    if (!bent(agent)) return commands_[agent].velocity * time;
    return travelled_on(leg_[agent], time);
  }
  static Vec2 travelled_on(const Leg& leg, double time) {
    if (leg.velocity.x == 0.0 && leg.velocity.y == 0.0) return leg.origin;
    return leg.origin + leg.velocity * (time - leg.start);
  }
  // The velocity of the agent's current leg (events are processed in time order).
  Vec2 velocity_after(std::uint32_t agent) const {
    return bent(agent) ? leg_[agent].velocity : commands_[agent].velocity;
  }

  std::span<const CandidatePair> pairs_;
  std::span<const MotionCommand> commands_;
  std::span<const Signal> signals_;
  std::span<const Vec2> positions_;
  MotionLimits limits_;
  EventOrder order_ = EventOrder::Auto;
  bool by_island_ = false;  // this step's order
  // Islands of this step: union-find's parents, valid where island_stamp_ == step_stamp_,
  // and the islands' numbers by root, valid where number_stamp_ == step_stamp_.
  AgentArray<std::uint32_t> island_parent_;
  AgentArray<std::uint32_t> island_stamp_;
  AgentArray<std::uint32_t> island_number_;
  AgentArray<std::uint32_t> number_stamp_;
  std::uint32_t islands_ = 0;       // numbered so far (ordered by island)
  std::uint32_t event_island_ = 0;  // of the event being processed (0 unless by island)
  std::vector<std::uint32_t> island_begin_;
  bool starting_ = false;  // events go to start_events_, not to the heap
  std::vector<Event> start_events_;
  std::vector<Event> sorted_events_;
  std::vector<std::size_t> slot_begin_;
  std::size_t next_start_ = 0;
  std::vector<Event> heap_;
  // Legs of the agents whose motion changed this step (leg_stamp_ == step_stamp_); the
  // others move with their commanded velocity all step.
  std::uint32_t step_stamp_ = 0;
  AgentArray<Leg> leg_;
  AgentArray<std::uint32_t> leg_stamp_;
  std::vector<std::uint32_t> bent_agents_;
  std::vector<std::uint32_t> met_agents_;
  AgentArray<std::uint8_t> slides_;
  AgentArray<std::uint8_t> walls_touched_;
  // Versions tell stale events from current ones: they count up across steps and are never
  // reset.
  AgentArray<std::uint32_t> version_;
  // Pairs of each agent, built on the first change of a step: the pair ends (2 * pair + end)
  // of agent a are incident_ends_[incidence_begin_[a] .. incidence_begin_[a + 1]), so that
  // rescheduling an agent reads one short contiguous run.
  bool incidence_built_ = false;
  AgentArray<std::uint32_t> incidence_begin_;
  AgentArray<Incidence> incident_ends_;
  // The other agent of each of an agent's pairs, with its velocity and displacement at the
  // time they were gathered.
  struct Neighbour {
    std::uint32_t end;
    std::uint32_t other;
    Vec2 velocity;
    Vec2 travelled;
  };
  std::vector<Neighbour> neighbours_;
  std::size_t neighbour_count_ = 0;
  std::span<Neighbour> neighbours() { return {neighbours_.data(), neighbour_count_}; }
  std::vector<std::pair<std::uint32_t, Vec2>> contacts_;  // of the agent sliding, by id
  std::vector<Vec2> normals_;
};

}  // namespace swarmagg
