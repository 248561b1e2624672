#pragma once
// Circle-packing estimates for an aggregate of m agents shared by both models (Bayindir's
// fit): outer radius R1(m) = r * 1.20 * m^0.48 for agents of radius r, and the number of
// agents on its periphery pi (1.20 m^0.48 - 1) (docs/models.md; the paper prints sqrt(m)).
namespace swarmagg {

// The paper's fit (Fig 6): R1 = r a m^b and periph = pi (a m^b - 1) with these a, b.
inline constexpr double kPaperPackingScale = 1.20;
inline constexpr double kPaperPackingExponent = 0.48;

double aggregate_radius(double agent_radius, double size);

// Uncapped: exceeds m for small m (3.25, 4.19, 5.02 for m = 3, 4, 5).
double periphery_agents(double size);
// min(m, periphery_agents(m)): a periphery cannot hold more agents than the aggregate has.
double capped_periphery_agents(double size);

}  // namespace swarmagg
