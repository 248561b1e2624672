// The kinematic engine and the controllers hold no absolute length: a world whose lengths
// (arena, radii, speed, compaction spacing and tolerance, approach radius) are all multiplied
// by a power of two runs the same, bit for bit (such a product is exact in doubles). This is
// what lets the world keys accept lengths anywhere in 1e-30 .. 1e30; a tolerance written as an
// absolute length (heading_away compared a length with 1e-12 u) breaks it at small scales.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/world_keys.hpp"
#include "config/world_loader.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// Written as a world file would be, so that every default derived from a length follows.
WorldSpec scaled_world(const std::string& controller, const std::string& topology, double scale) {
  const auto length = [scale](double value) { return format_number(value * scale); };
  std::string controller_keys = "type: " + controller +
                                ", compaction: {tolerance: " + length(0.05) +
                                ", spacing: " + length(2.0) + "}";
  if (controller == "bayindir") controller_keys += ", p_leave: 0.01";
  if (controller == "soysal") controller_keys += ", approach_radius: " + length(12.0);
  return load_world_text(
      "name: scaled\narena: {width: " + length(60) + ", height: " + length(60) +
          ", topology: " + topology + "}\nrobots: {count: 40, radius: " + length(1) +
          ", detection_radius: " + length(4) + ", speed: " + length(1) + "}\ncontroller: {" +
          controller_keys + "}\nrun: {duration: 100, seed: 3}\n",
      "scale-test");
}

void expect_same_run_at_scale(const std::string& controller, const std::string& topology,
                              double scale) {
  SCOPED_TRACE(controller + " on " + topology + " scaled by " + std::to_string(scale));
  const WorldSpec unit_world = scaled_world(controller, topology, 1.0);
  const WorldSpec scaled_world_spec = scaled_world(controller, topology, scale);
  Replicate unit(unit_world, 0);
  Replicate scaled(scaled_world_spec, 0);
  int waited = 0;
  for (int step = 0; step < 1000; ++step) {
    unit.step();
    scaled.step();
    const std::span<const Vec2> a = unit.engine().positions();
    const std::span<const Vec2> b = scaled.engine().positions();
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].x * scale, b[i].x) << "agent " << i << " at step " << step;
      ASSERT_EQ(a[i].y * scale, b[i].y) << "agent " << i << " at step " << step;
      ASSERT_EQ(unit.swarm().state[i], scaled.swarm().state[i]) << "agent " << i;
      waited += unit.swarm().state[i] == AgentState::Wait;
    }
  }
  EXPECT_GT(waited, 1000) << "the world formed no aggregates: nothing was compared";
}

TEST(ScaleInvariance, APowerOfTwoScaleOfEveryLengthGivesTheSameRun) {
  for (const double scale : {std::ldexp(1.0, -60), std::ldexp(1.0, 60)}) {
    expect_same_run_at_scale("bayindir", "torus", scale);
    expect_same_run_at_scale("soysal", "torus", scale);
    expect_same_run_at_scale("bayindir", "walls", scale);
  }
}

}  // namespace
}  // namespace swarmagg
