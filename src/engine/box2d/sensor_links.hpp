#pragma once
// The pairs of agents whose sensors touch, kept from Box2D's sensor begin/end events. One
// pair of agents can touch through several fixture pairs at once (a body and the periodic
// image of the other, or two images near the same edge), so each link counts its touching
// fixture pairs per sensor kind: the agents perceive each other while the count is > 0, and
// the count going 0 -> 1 is the moment they came within range. Storage is one small vector
// per agent, reused, so steady-state stepping allocates nothing.
#include <cstdint>
#include <span>
#include <vector>

#include "control_interface/neighbour_lists.hpp"

namespace swarmagg::box2d {

enum class SensorKind : std::uint8_t { Detect, Sense };

struct SensorLink {
  AgentId other = 0;
  std::uint16_t detect = 0;  // touching detection-sensor pairs (centres within s)
  std::uint16_t sense = 0;   // touching sensing-sensor pairs (within the sensing radius)
};

class SensorLinks {
 public:
  void reset(std::size_t agent_count);
  // A fixture pair of agents a and b started touching; true if the agents were not linked
  // through this kind of sensor before (they just came within its range).
  bool begin(AgentId a, AgentId b, SensorKind kind);
  // A fixture pair stopped touching (or was destroyed while touching).
  void end(AgentId a, AgentId b, SensorKind kind);
  std::span<const SensorLink> of(AgentId agent) const { return links_[agent]; }

 private:
  SensorLink& find_or_add(AgentId a, AgentId b);
  std::vector<std::vector<SensorLink>> links_;
};

}  // namespace swarmagg::box2d
