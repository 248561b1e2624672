#pragma once
// Exact first-contact time of two discs moving with constant velocities: the first time in
// [t0, t1] at which their centre distance reaches `reach`. Within a step velocities are
// constant, so this is the smaller root of |d + w t|^2 = reach^2, and no encounter is missed
// however far the agents move in one step.
#include <optional>

#include "core/vec2.hpp"

namespace swarmagg {

// `offset` is the displacement from a to b at time t0, `relative_velocity` is v_b - v_a.
// Returns the contact time in [t0, t1] if the pair is farther apart than `reach` at t0 and
// comes within it by t1; nothing otherwise (already in contact, or never reaching).
std::optional<double> first_contact_time(Vec2 offset, Vec2 relative_velocity, double reach,
                                         double t0, double t1);

// True when two bodies already within `reach` are moving closer (their distance decreasing).
inline bool approaching(Vec2 offset, Vec2 relative_velocity) {
  return dot(offset, relative_velocity) < 0.0;
}

}  // namespace swarmagg
