#include "models/aggregate_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swarmagg {

namespace {
constexpr double kPackingScale = 1.20;
constexpr double kPackingExponent = 0.48;
}  // namespace

double aggregate_radius(double agent_radius, double size) {
  return agent_radius * kPackingScale * std::pow(size, kPackingExponent);
}

double periphery_agents(double size) {
  return std::numbers::pi * (kPackingScale * std::pow(size, kPackingExponent) - 1.0);
}

double capped_periphery_agents(double size) {
  return std::min(size, periphery_agents(size));
}

}  // namespace swarmagg
