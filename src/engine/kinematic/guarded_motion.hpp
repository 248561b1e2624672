#pragma once
// Resolves one kinematic step exactly. Agents move with constant commanded velocities; the
// pair events of the step (centres reaching the detection radius s, bodies reaching contact
// at 2r) are processed in time order. An agent halts at the instant an event its command
// cares about fires (halt_on, blocked_by); its later events are then recomputed from its
// new, stationary trajectory. Every first contact within s is counted as an encounter.
// When no command guards its move, nothing can halt and the encounters are simply counted.
#include <cstdint>
#include <span>
#include <vector>

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

struct MotionLimits {
  double detection_radius = 4.0;  // s
  double contact_distance = 2.0;  // 2r
  double dt = 0.1;
};

class GuardedMotion {
 public:
  // Resolves the step for agents that guard their moves (some command has halt_on or
  // blocked_by bits) and returns the number of encounters; stop_times() then holds when
  // each agent stopped (dt when it moved the whole step).
  std::uint64_t resolve(std::span<const CandidatePair> pairs,
                        std::span<const MotionCommand> commands, std::span<const Signal> signals,
                        const MotionLimits& limits);
  std::span<const double> stop_times() const { return stop_time_; }

  // The encounters of a step in which no agent halts: every agent moves the whole step.
  static std::uint64_t count_encounters(std::span<const CandidatePair> pairs,
                                        std::span<const MotionCommand> commands,
                                        const MotionLimits& limits);

 private:
  enum class Kind : std::uint8_t { Perceive, Contact };
  struct Event {
    double time;
    std::uint32_t pair;
    Kind kind;
    std::uint32_t version_i;
    std::uint32_t version_j;
  };
  struct Later {  // heap order: the earliest event on top
    const CandidatePair* pairs;
    bool operator()(const Event& a, const Event& b) const;
  };

  void reset(std::size_t agents, double dt);
  void schedule_pair(std::uint32_t pair, double from_time);
  void halt(std::uint32_t agent, double time);
  void build_incidence();
  bool blocks(std::uint32_t mover, std::uint32_t other) const;
  bool halts_for(std::uint32_t mover, std::uint32_t other) const;
  Vec2 displacement_travelled(std::uint32_t agent, double time) const;
  Vec2 velocity_after(std::uint32_t agent, double time) const;

  std::span<const CandidatePair> pairs_;
  std::span<const MotionCommand> commands_;
  std::span<const Signal> signals_;
  MotionLimits limits_;
  AgentArray<double> stop_time_;
  std::vector<std::uint32_t> halted_;  // agents whose stop time is below dt
  std::vector<Event> heap_;
  // An agent halts at most once per step (later events are never earlier), so versions
  // only need to differ within a step: they count up across steps and are never reset.
  AgentArray<std::uint32_t> version_;
  // Pairs of each agent, built on the first halt of a step: linked lists through the pair
  // ends (2 * pair + end), whose heads are valid only where head_stamp_ is this step's.
  bool incidence_built_ = false;
  std::uint32_t stamp_ = 0;
  AgentArray<std::uint32_t> head_;
  AgentArray<std::uint32_t> head_stamp_;
  AgentArray<std::uint32_t> next_end_;
};

}  // namespace swarmagg
