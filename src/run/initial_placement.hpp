#pragma once
// Initial positions and headings of one replicate: the world's explicit placement, or
// uniform random positions without body overlap (detection discs may overlap, as in the
// paper) and uniform random headings, all drawn from the replicate's generator.
// Random placements of 4096 agents or more number the agents in spatial order (see the .cpp).
#include <vector>

#include "config/world_spec.hpp"
#include "core/rng.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

struct InitialPlacement {
  std::vector<Vec2> positions;
  std::vector<Vec2> headings;
};

InitialPlacement place_agents(const WorldSpec& spec, const CounterRng& rng);

}  // namespace swarmagg
