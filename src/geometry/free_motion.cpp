#include "geometry/free_motion.hpp"

#include <cmath>

namespace swarmagg {
namespace {

// Tangential slides are computed in floating point: a slide may still press into its own
// contact by a rounding error, which must not count as pressing into it.
constexpr double kRoundingSlack = 1e-12;
// A slide takes off a hair more than the normal component, so that it leaves its contact
// (at 1e-9 of the speed it pressed with) rather than grazing it within rounding.
constexpr double kLeaveContact = 1.0 + 1e-9;
// A slide slower than this fraction of the desired speed is a head-on press.
constexpr double kHeadOn = 1e-8;

bool presses_into_none(Vec2 d, std::span<const Vec2> normals, double slack) {
  for (const Vec2& n : normals) {
    if (dot(d, n) > slack) return false;
  }
  return true;
}

}  // namespace

// In the plane the projection on a cone of half-planes lies on the face of one pressed
// contact (v minus its normal component) or at the apex (zero); of the faces that press into
// no other contact, the nearest to v is the longest.
Vec2 free_motion(Vec2 velocity, std::span<const Vec2> normals) {
  const double slack = kRoundingSlack * norm(velocity);
  if (presses_into_none(velocity, normals, slack)) return velocity;
  Vec2 best;
  double best_length2 = 0.0;
  for (const Vec2& n : normals) {
    const double pressing = dot(velocity, n);
    if (pressing <= slack) continue;
    // Head on, nothing is left but rounding: that face lets nothing through.
    if (norm2(velocity - n * pressing) <= kHeadOn * kHeadOn * norm2(velocity)) continue;
    const Vec2 slide = velocity - n * (pressing * kLeaveContact);
    if (norm2(slide) > best_length2 && presses_into_none(slide, normals, slack)) {
      best = slide;
      best_length2 = norm2(slide);
    }
  }
  return best;
}

}  // namespace swarmagg
