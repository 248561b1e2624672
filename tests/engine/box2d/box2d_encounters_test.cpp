// Encounters in ghost mode (agents pass over each other) against kinetic theory (docs/models.md):
// y agents at speed v with independent uniform headings on area A meet at
// Z = (4/pi) s v y (y - 1) / A first contacts per tu.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/box2d/box2d_test_support.hpp"

namespace swarmagg {
namespace {

using namespace swarmagg::testing;

TEST(Box2DEncounters, GhostModeRateMatchesKineticTheory) {
  constexpr int kAgents = 200;
  constexpr int kSteps = 4000;
  constexpr double kSide = 200.0;
  constexpr double kTumble = 0.01;  // heading redraws per step: no periodic orbits
  const WorldSpec spec = box2d_world(kSide, kSide, kAgents);
  const auto start = random_positions(spec, kAgents, 2.0, 61);
  auto engine = make_box2d_engine(spec, start);
  auto headings = random_headings(kAgents, 62);
  std::mt19937_64 rng(63);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<MotionCommand> commands(kAgents);
  const std::vector<Signal> signals(kAgents, kGo);
  std::uint64_t encounters = 0;
  for (int k = 0; k < kSteps; ++k) {
    for (int i = 0; i < kAgents; ++i) {
      if (u(rng) < kTumble) headings[i] = from_angle(2.0 * kPi * u(rng));
      commands[i].velocity = headings[i];  // v = 1, blocked_by = 0: ghosts
    }
    encounters += engine->step(commands, signals).encounters;
  }
  const double duration = kSteps * spec.engine.dt;
  const double expected =
      (4.0 / kPi) * 4.0 * 1.0 * kAgents * (kAgents - 1) / (kSide * kSide) * duration;
  const double sigma = std::sqrt(expected);  // Poisson counting
  std::printf("encounters %llu, kinetic theory %.1f +- %.1f\n",
              static_cast<unsigned long long>(encounters), expected, sigma);
  EXPECT_NEAR(static_cast<double>(encounters), expected, 4.5 * sigma);
}

}  // namespace
}  // namespace swarmagg
