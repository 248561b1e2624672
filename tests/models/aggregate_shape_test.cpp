#include "models/aggregate_shape.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(AggregateShape, PeripheryMatchesTheValuesQuotedInTheSpec) {
  // docs/models.md: 3.25, 4.19, 5.02 for i = 3, 4, 5 (pi (1.20 i^0.48 - 1), uncapped).
  EXPECT_NEAR(periphery_agents(3), 3.2461780906421134, 1e-12);
  EXPECT_NEAR(periphery_agents(4), 4.192052875853893, 1e-12);
  EXPECT_NEAR(periphery_agents(5), 5.02116157966924, 1e-12);
  EXPECT_NEAR(periphery_agents(10), 8.243357113223203, 1e-12);
}

TEST(AggregateShape, RadiusScalesWithAgentRadius) {
  EXPECT_NEAR(aggregate_radius(1.0, 2), 1.6736923996204864, 1e-12);  // 1.2 * 2^0.48
  EXPECT_NEAR(aggregate_radius(2.5, 2), 2.5 * 1.6736923996204864, 1e-12);
}

}  // namespace
}  // namespace swarmagg
