#include "geometry/swept_contact.hpp"

#include <cmath>

namespace swarmagg {

std::optional<double> first_contact_time(Vec2 offset, Vec2 relative_velocity, double reach,
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

}  // namespace swarmagg
