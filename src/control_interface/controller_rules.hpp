#pragma once
// What a controller allows, computed once from the world by the controller itself
// (controllers/controller_registry.hpp) and read by everything else that must know it: the
// replicate (how aggregates link), the invariants, the outputs, compare, the models, the
// renderer and the bench. Nothing outside a controller's folder re-derives these.
#include <cstdint>

#include "core/agent_state.hpp"

namespace swarmagg {

// Which macroscopic model describes the controller's worlds (docs/models.md).
enum class ModelFamily : std::uint8_t {
  None,        // no model: no predictions are written
  Encounters,  // only the kinetic encounter rate (the collision check)
  Bayindir,    // the NOA model
  Soysal,      // the partition model
};

struct ControllerRules {
  // Bit k set: AgentState k may occur.
  unsigned allowed_states = 0;
  // Searching agents may join waiting ones (growth events; searchers blocked by waiting bodies).
  bool joins = false;
  // Waiting agents may leave (dissipation and shrink events, LEAVE states).
  bool leaves = false;
  // Leaving happens with a nonzero probability (compare's rim and inside leave statistics).
  bool leaving_happens = false;
  // Agents aggregate at all (false: nothing but encounters is ever counted).
  bool aggregates = true;
  // Waiting agents move to close up their aggregate (docs/controllers.md, "Compaction"); without it
  // they stand still.
  bool compacts = false;
  // Only partners (the two agents that formed a pair) are linked into aggregates.
  bool partners_only = false;
  // Partition occupancy is an output (partitions.csv).
  bool records_partitions = false;
  ModelFamily model = ModelFamily::None;

  bool allows(AgentState state) const {
    return (allowed_states >> static_cast<unsigned>(state)) & 1u;
  }
};

constexpr unsigned state_bit(AgentState state) {
  return 1u << static_cast<unsigned>(state);
}

}  // namespace swarmagg
