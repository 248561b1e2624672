#pragma once
// Worlds of any size at the paper's density, for benchmarks and large-swarm tests.
#include "config/world_spec.hpp"

namespace swarmagg {

// n agents with the default robots on a square torus at the paper's density (150 agents per
// 180 x 180, the side scaled with sqrt(n)), one replicate. Collision runs in ghost mode (the
// worst case: every agent moves every step), Bayindir's full model with p_leave = 0.001.
WorldSpec paper_density_world(int n, const std::string& type);

}  // namespace swarmagg
