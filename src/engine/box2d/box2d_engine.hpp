#pragma once
// The Box2D 2.4 engine (SPEC section 2): every agent is a dynamic disc body of radius r with
// a sensor fixture for detection; contacts are real, WAIT-like signals repel others, and the
// torus seam is handled by periodic ghost bodies whose impulses flow back to their owners.
#include <memory>
#include <span>

#include "config/world_spec.hpp"
#include "core/vec2.hpp"
#include "engine/engine.hpp"

namespace swarmagg {

// Throws InputError when the world cannot be run faithfully by Box2D (for example a speed
// above the per-step translation cap that substepping cannot bring under it).
std::unique_ptr<Engine> make_box2d_engine(const WorldSpec& spec,
                                          std::span<const Vec2> initial_positions);

}  // namespace swarmagg
