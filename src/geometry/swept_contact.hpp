#pragma once
// Exact first-contact time of two discs moving with constant velocities: the first time in
// [t0, t1] at which their centre distance reaches `reach`. Within a step velocities are
// constant, so this is the smaller root of |d + w t|^2 = reach^2, and no encounter is missed
// however far the agents move in one step.
#include <cmath>
#include <optional>

#include "core/vec2.hpp"

namespace swarmagg {

// `offset` is the displacement from a to b at time t0, `relative_velocity` is v_b - v_a.
// Returns the contact time in [t0, t1] if the pair is farther apart than `reach` at t0 and
// comes within it by t1; nothing otherwise (already in contact, or never reaching). Inline:
// the guarded motion calls it for every moving pair, mostly to learn that nothing happens.
inline std::optional<double> first_contact_time(Vec2 offset, Vec2 relative_velocity, double reach,
                                                double t0, double t1) {
  const double c = norm2(offset) - reach * reach;
  if (c <= 0.0) return std::nullopt;  // already within reach: not a first contact
  const double a = norm2(relative_velocity);
  const double b = dot(offset, relative_velocity);
  if (a == 0.0 || b >= 0.0) return std::nullopt;  // not moving closer
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return std::nullopt;  // passes by farther than reach
  // Smaller root of a t^2 + 2 b t + c = 0, written to avoid cancellation (b < 0).
  const double tau = c / (-b + std::sqrt(discriminant));
  if (t0 + tau > t1) return std::nullopt;
  return t0 + tau;
}

// True when two bodies already within `reach` are moving closer (their distance decreasing).
inline bool approaching(Vec2 offset, Vec2 relative_velocity) {
  return dot(offset, relative_velocity) < 0.0;
}

}  // namespace swarmagg
