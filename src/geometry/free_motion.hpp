#pragma once
// The part of a desired motion that touching bodies let through. A body pressed against
// others at unit normals n_k (from the body towards each one it touches) may move in any
// direction d with d . n_k <= 0 for every k; the free part of a desired velocity v is the
// nearest such d to v (its projection on that cone): v itself when it presses into nothing,
// v without its normal component when it presses into one body (it slides along it), zero
// when it presses into a wedge of bodies (a slide leaves its contact at 1e-9 of the normal
// speed removed, so that rounding never makes it press in again). The kinematic engine slides
// bodies along their contacts with it.
#include <span>

#include "core/vec2.hpp"

namespace swarmagg {

Vec2 free_motion(Vec2 velocity, std::span<const Vec2> normals);

}  // namespace swarmagg
