#pragma once
// What an agent displays to the others during a step: its controller state, as a robot
// would show an LED colour. Engines read only the signal; the mapping is this one function.
#include <cstddef>
#include <span>

#include "control_interface/motion_command.hpp"
#include "core/agent_state.hpp"

namespace swarmagg {

constexpr Signal signal_of(AgentState state) {
  return static_cast<Signal>(state);
}
static_assert(kAgentStateCount <= 16, "a SignalMask holds 16 signals");

// signals[i] = signal_of(states[i]); both spans hold the same number of agents.
inline void write_signals(std::span<const AgentState> states, std::span<Signal> signals) {
  const AgentState* in = states.data();
  Signal* out = signals.data();
  for (std::size_t i = 0; i < states.size(); ++i) out[i] = signal_of(in[i]);
}

}  // namespace swarmagg
