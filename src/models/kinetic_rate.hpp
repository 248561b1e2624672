#pragma once
// Encounter rates of agents moving straight at speed v with detection radius s on area A
// (docs/models.md): Z = kappa s v y(y-1) / A per tu, kappa = 4/pi from kinetic theory (mean
// relative speed 4v/pi, collision width 2s, y(y-1)/2 pairs), sqrt 2 as Bayindir had it, or
// the paper's fitted Z = C s v y^2 (no area: formula (6) times A^2). Creation of a Bayindir
// model is the same rate per step of dt among the searching agents.
#include "config/world_spec.hpp"

namespace swarmagg {

// The paper's fitted constant C = sqrt(2) / 1.15e5 of formula (6).
inline constexpr double kPaperCollisionConstant = 1.4142135623730951 / 1.15e5;

enum class PairCount {
  Ordered,  // y (y - 1): ordered pairs of distinct agents
  Squared,  // y^2: Bayindir's original and the paper's fit
};

// rate(y) = coefficient * pairs(y).
struct PairRate {
  double coefficient = 0.0;
  PairCount pairs = PairCount::Ordered;
  // For the expected-value model y is real; y (y - 1) is clamped at 0 because the expected
  // number of pairs E[y (y - 1)] is never negative, even when E[y] < 1.
  double at(double agents) const;
};

double kappa_value(Kappa kappa);  // 4/pi or sqrt 2; the paper's form has no kappa (throws)

// Encounters per tu among y agents.
PairRate encounter_rate(Kappa kappa, double detection_radius, double speed, double area);

// Expected creations per step among y searchers for a Bayindir creation variant: `original`
// is sqrt 2 s v dt y^2 / A; `collision` is encounter_rate(model.kappa) * dt.
PairRate creation_per_step(const WorldSpec& world, CreationVariant variant);

}  // namespace swarmagg
