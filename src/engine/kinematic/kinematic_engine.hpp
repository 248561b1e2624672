#pragma once
// The paper's SWARM-AGG engine, made exact: finite-size points moving with their commanded
// velocities, guarded moves and contacts resolved at the exact instant within the step,
// neighbour search in sorted strips (O(N) per step), torus or reflecting walls.
#include <memory>
#include <span>

#include "config/world_spec.hpp"
#include "engine/engine.hpp"

namespace swarmagg {

std::unique_ptr<Engine> make_kinematic_engine(const WorldSpec& spec,
                                              std::span<const Vec2> initial_positions);

}  // namespace swarmagg
