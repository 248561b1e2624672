#pragma once
// Resolves one kinematic step exactly. Agents move with constant commanded velocities; the
// pair events of the step (centres reaching the detection radius s, bodies reaching contact
// at 2r) are processed in time order. An agent halts at the instant an event its command
// cares about fires (halt_on, blocked_by); its later events are then recomputed from its
// new, stationary trajectory. Every first contact within s is counted as an encounter.
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec2.hpp"
#include "engine/motion_command.hpp"

namespace swarmagg {

// Two agents that may meet during the step: i < j, `offset` from i to j at the step start.
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
  // Fills stop_time[i] (dt when agent i moves the whole step) and returns the number of
  // encounters of the step.
  std::uint64_t resolve(std::span<const CandidatePair> pairs, std::span<const MotionCommand> commands,
                        std::span<const Signal> signals, const MotionLimits& limits,
                        std::vector<double>& stop_time);

 private:
  enum class Kind : std::uint8_t { Perceive, Contact };
  struct Event {
    double time;
    std::uint32_t pair;
    Kind kind;
    std::uint32_t version_i;
    std::uint32_t version_j;
  };

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
  std::vector<double>* stop_time_ = nullptr;
  std::vector<Event> heap_;
  std::vector<std::uint32_t> version_;
  bool incidence_built_ = false;
  std::vector<std::uint32_t> incidence_start_;
  std::vector<std::uint32_t> incidence_;
  std::vector<std::uint32_t> incidence_cursor_;
};

}  // namespace swarmagg
