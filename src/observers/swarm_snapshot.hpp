#pragma once
// A read-only view of one replicate at one step: what outputs and rendering may see.
#include <cstdint>
#include <span>

#include "config/world_spec.hpp"
#include "core/agent_state.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

struct SwarmSnapshot {
  const WorldSpec* spec = nullptr;
  std::int64_t step = 0;
  double time = 0.0;
  std::span<const Vec2> positions;
  std::span<const AgentState> states;
  // Aggregate index of each agent (0 .. noa-1), or -1 for agents in no aggregate.
  std::span<const std::int32_t> aggregate;
  int noa = 0;
};

}  // namespace swarmagg
