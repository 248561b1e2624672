#include "geometry/free_motion.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace swarmagg {
namespace {

TEST(FreeMotion, MotionIntoNothingPassesUnchanged) {
  const std::vector<Vec2> normals{{1.0, 0.0}};
  EXPECT_EQ(free_motion({-1.0, 0.5}, normals), (Vec2{-1.0, 0.5}));  // away from the contact
  EXPECT_EQ(free_motion({0.3, 0.4}, {}), (Vec2{0.3, 0.4}));
}

TEST(FreeMotion, PressingIntoOneContactSlidesAlongIt) {
  const std::vector<Vec2> normals{{1.0, 0.0}};
  const Vec2 slide = free_motion({1.0, 0.5}, normals);
  EXPECT_NEAR(slide.y, 0.5, 1e-12);
  EXPECT_LT(slide.x, 0.0);  // leaves the contact by a hair rather than grazing it
  EXPECT_GT(slide.x, -1e-8);
}

TEST(FreeMotion, HeadOnOrIntoAWedgeNothingIsLeft) {
  const std::vector<Vec2> one{{1.0, 0.0}};
  EXPECT_EQ(free_motion({2.0, 0.0}, one), (Vec2{}));
  // Two contacts 120 degrees apart, pressed between them: each slide runs into the other.
  const std::vector<Vec2> wedge{{0.5, 0.8660254037844386}, {0.5, -0.8660254037844386}};
  EXPECT_EQ(free_motion({1.0, 0.1}, wedge), (Vec2{}));
}

TEST(FreeMotion, ASlideMayNotRunIntoAnotherContact) {
  // Pressed down-right onto a floor beside a wall on the left: it slides right, away from the
  // wall. With the wall on the right instead it is in a corner and stops.
  const std::vector<Vec2> wall_left{{0.0, -1.0}, {-1.0, 0.0}};
  const Vec2 slide = free_motion({1.0, -1.0}, wall_left);
  EXPECT_NEAR(slide.x, 1.0, 1e-12);
  EXPECT_NEAR(slide.y, 0.0, 1e-8);
  const std::vector<Vec2> corner{{0.0, -1.0}, {1.0, 0.0}};
  EXPECT_EQ(free_motion({1.0, -1.0}, corner), (Vec2{}));
}

}  // namespace
}  // namespace swarmagg
