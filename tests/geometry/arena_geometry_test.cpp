#include "geometry/arena_geometry.hpp"

#include <gtest/gtest.h>

namespace swarmagg {
namespace {

TEST(ArenaGeometry, DisplacementAcrossTheSeamIsTheShortestImage) {
  const ArenaGeometry torus(100.0, 50.0, Topology::Torus);
  const Vec2 d = torus.displacement({99.0, 1.0}, {1.0, 49.0});
  EXPECT_DOUBLE_EQ(d.x, 2.0);
  EXPECT_DOUBLE_EQ(d.y, -2.0);
  EXPECT_DOUBLE_EQ(torus.distance({99.0, 1.0}, {1.0, 49.0}), std::sqrt(8.0));
}

TEST(ArenaGeometry, DisplacementIsAntisymmetric) {
  const ArenaGeometry torus(100.0, 100.0, Topology::Torus);
  const Vec2 a{3.0, 97.0};
  const Vec2 b{95.0, 4.0};
  const Vec2 ab = torus.displacement(a, b);
  const Vec2 ba = torus.displacement(b, a);
  EXPECT_DOUBLE_EQ(ab.x, -ba.x);
  EXPECT_DOUBLE_EQ(ab.y, -ba.y);
}

TEST(ArenaGeometry, WallsUseThePlainDifference) {
  const ArenaGeometry walls(100.0, 100.0, Topology::Walls);
  const Vec2 d = walls.displacement({99.0, 1.0}, {1.0, 99.0});
  EXPECT_DOUBLE_EQ(d.x, -98.0);
  EXPECT_DOUBLE_EQ(d.y, 98.0);
  EXPECT_EQ(walls.wrap({-1.0, 101.0}), (Vec2{-1.0, 101.0}));
}

TEST(ArenaGeometry, WrapBringsEveryPointInsideTheArena) {
  const ArenaGeometry torus(10.0, 20.0, Topology::Torus);
  EXPECT_EQ(torus.wrap({-0.5, 20.5}), (Vec2{9.5, 0.5}));
  EXPECT_EQ(torus.wrap({10.0, -20.0}), (Vec2{0.0, 0.0}));
  EXPECT_EQ(torus.wrap({35.0, 41.0}), (Vec2{5.0, 1.0}));
  const Vec2 tiny = torus.wrap({-1e-18, 3.0});
  EXPECT_GE(tiny.x, 0.0);
  EXPECT_LT(tiny.x, 10.0);
}

}  // namespace
}  // namespace swarmagg
