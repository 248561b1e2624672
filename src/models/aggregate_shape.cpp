#include "models/aggregate_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swarmagg {

double aggregate_radius(double agent_radius, double size) {
  return agent_radius * kPaperPackingScale * std::pow(size, kPaperPackingExponent);
}

double periphery_agents(double size) {
  return std::numbers::pi * (kPaperPackingScale * std::pow(size, kPaperPackingExponent) - 1.0);
}

double capped_periphery_agents(double size) {
  return std::min(size, periphery_agents(size));
}

}  // namespace swarmagg
