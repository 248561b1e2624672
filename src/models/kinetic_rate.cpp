#include "models/kinetic_rate.hpp"

#include <algorithm>
#include <numbers>
#include <stdexcept>

namespace swarmagg {

double PairRate::at(double agents) const {
  const double pairs_count =
      pairs == PairCount::Squared ? agents * agents : std::max(0.0, agents * (agents - 1.0));
  return coefficient * pairs_count;
}

double kappa_value(Kappa kappa) {
  switch (kappa) {
    case Kappa::Kinetic:
      return 4.0 / std::numbers::pi;
    case Kappa::Maxwell:
      return std::numbers::sqrt2;
    case Kappa::Paper:
      break;
  }
  throw std::logic_error("kappa: paper is a fitted constant, not a kappa");
}

PairRate encounter_rate(Kappa kappa, double detection_radius, double speed, double area) {
  if (kappa == Kappa::Paper) {
    return {kPaperCollisionConstant * detection_radius * speed, PairCount::Squared};
  }
  return {kappa_value(kappa) * detection_radius * speed / area, PairCount::Ordered};
}

PairRate creation_per_step(const WorldSpec& world, CreationVariant variant) {
  const double s = world.robots.detection_radius;
  const double v = world.robots.speed;
  const double dt = world.engine.dt;
  if (variant == CreationVariant::Original) {
    return {kappa_value(Kappa::Maxwell) * s * v * dt / world.arena.area(), PairCount::Squared};
  }
  PairRate rate = encounter_rate(world.model.kappa, s, v, world.arena.area());
  rate.coefficient *= dt;
  return rate;
}

}  // namespace swarmagg
