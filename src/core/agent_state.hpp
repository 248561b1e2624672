#pragma once
// The controller state of every agent of one replicate (mutable, owned by the replicate).
// The state value doubles as the signal an agent displays to the engine (motion_command.hpp).
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/agent_array.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

enum class AgentState : std::uint8_t { Go = 0, Wait = 1, Leave = 2, Approach = 3 };
constexpr int kAgentStateCount = 4;

constexpr std::string_view to_string(AgentState s) {
  switch (s) {
    case AgentState::Go:
      return "GO";
    case AgentState::Wait:
      return "WAIT";
    case AgentState::Leave:
      return "LEAVE";
    case AgentState::Approach:
      return "APPROACH";
  }
  return "?";
}

constexpr std::int32_t kNoPartner = -1;

struct SwarmState {
  AgentArray<AgentState> state;
  AgentArray<Vec2> heading;            // unit vector of the current straight-line motion
  AgentArray<double> leave_time_left;  // tu left in LEAVE
  AgentArray<std::int32_t> partner;    // the agent a pair formed with (join: false), or kNoPartner

  void resize(std::size_t n) {
    state.assign(n, AgentState::Go);
    heading.assign(n, Vec2{1.0, 0.0});
    leave_time_left.assign(n, 0.0);
    partner.assign(n, kNoPartner);
  }
  std::size_t size() const { return state.size(); }
  // Appends an agent in `s`, heading +x, outside any pair; returns its index (test scenes).
  std::uint32_t add(AgentState s) {
    state.push_back(s);
    heading.push_back({1.0, 0.0});
    leave_time_left.push_back(0.0);
    partner.push_back(kNoPartner);
    return static_cast<std::uint32_t>(state.size() - 1);
  }
};

}  // namespace swarmagg
