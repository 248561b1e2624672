#pragma once
// The Box2D 2.4 engine (docs/architecture.md). Every agent is a dynamic disc body of radius r with
// sensor discs whose begin/end events give its perceived agents and first contacts; contacts
// between bodies are real where MotionCommand::blocked_by says so, guarded moves stop a body
// in the (sub)step its sensor fired, and repelled_by signals push a body away within s. On a
// torus an agent near an edge carries periodic images of its fixtures on its own body, so
// sensing and collisions across the seam are exactly those of mid-arena (periodic_body.hpp).
// Steps are cut into substeps so Box2D never clamps a body's speed.
#include <memory>
#include <span>

#include "config/world_spec.hpp"
#include "core/vec2.hpp"
#include "engine/engine.hpp"

namespace swarmagg {

// Throws InputError when the world cannot be run faithfully by Box2D (a torus too small for
// the periodic images, a speed needing thousands of substeps per step, ...).
std::unique_ptr<Engine> make_box2d_engine(const WorldSpec& spec,
                                          std::span<const Vec2> initial_positions);
// The same checks without building the engine: what a command that runs Box2D later (compare's
// second arm) asks before its first step.
void check_box2d_world(const WorldSpec& spec);

}  // namespace swarmagg
