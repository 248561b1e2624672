#pragma once
// The size a join is counted at (count_growth_by_size): the aggregate of the nearest agent
// within `radius` that waited before the decision. Controllers count growths by it, and the
// measured rates take returns out of those growths by the same rule (observers/leave_episodes),
// so a return falls under the size its growth did.
#include <cstdint>
#include <span>

#include "control_interface/neighbour_lists.hpp"
#include "core/agent_state.hpp"

namespace swarmagg {

// `neighbours` nearest first; `before`: every agent's state before the decision. 0 when no
// agent within `radius` waited (a pair formed).
inline std::int32_t joined_aggregate_size(std::span<const Neighbour> neighbours, double radius,
                                          std::span<const AgentState> before,
                                          std::span<const std::int32_t> size_of_agent) {
  for (const Neighbour& nb : neighbours) {
    if (nb.distance > radius) break;
    if (before[nb.id] == AgentState::Wait) return size_of_agent[nb.id];
  }
  return 0;
}

}  // namespace swarmagg
