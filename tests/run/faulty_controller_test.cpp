// A controller is the user's code. What a faulty one does is reported naming the controller,
// the replicate, the step and the agent, on both engines, instead of spreading silently (a NaN
// velocity turned every Box2D body to NaN in one step, exit 0) or crashing later.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "config/world_keys.hpp"
#include "config/world_loader.hpp"
#include "controllers/controller.hpp"
#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;

const WorldKey& fault_key() {
  static const WorldKey key = name_choice_key(
      "controller.fault", "none", {"none", "nan", "inf", "fast", "throw", "odd", "resize"},
      "faulty");
  return key;
}

// Every agent searches along its heading; at step 5, agent 3 gets the world's fault.
class FaultyController final : public Controller {
 public:
  explicit FaultyController(std::string fault, double speed)
      : fault_(std::move(fault)), speed_(speed) {}
  void decide(const ControllerInput& input, SwarmState& swarm, const CounterRng& /*rng*/,
              std::span<MotionCommand> commands, EventCounts& /*events*/) override {
    for (std::size_t i = 0; i < commands.size(); ++i)
      commands[i] = MotionCommand{swarm.heading[i] * speed_, 0, 0, 0};
    if (input.step != 5) return;
    constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (fault_ == "nan") commands[3].velocity = {kNan, 0.0};
    if (fault_ == "inf") commands[3].velocity = {kInf, 0.0};
    if (fault_ == "fast") commands[3].velocity = {1e6, 0.0};
    if (fault_ == "throw") throw std::runtime_error("no rule for this neighbourhood");
    if (fault_ == "odd") throw 42;
    if (fault_ == "resize") swarm.state.push_back(AgentState::Go);
  }

 private:
  std::string fault_;
  double speed_;
};

double detection_radius(const WorldSpec& spec) {
  return spec.robots.detection_radius;
}

ControllerRegistration faulty_registration() {
  ControllerRegistration r;
  r.world = {"faulty", {fault_key()}, detection_radius, detection_radius, nullptr, {}};
  r.make = [](const WorldSpec& spec) -> std::unique_ptr<Controller> {
    return std::make_unique<FaultyController>(name_choice(spec, fault_key()), spec.robots.speed);
  };
  r.rules = [](const WorldSpec&) {
    ControllerRules rules;
    rules.allowed_states = state_bit(AgentState::Go);
    rules.model = ModelFamily::None;
    return rules;
  };
  return r;
}

// Before main, so before any world is read.
const bool kRegistered = (register_controller(faulty_registration()), true);

// The error of ten steps of the world with `fault` on `engine`, or "none".
std::string error_of(const std::string& fault, const std::string& engine = "kinematic") {
  const WorldSpec spec = load_world_text(
      "arena: {width: 60, height: 60}\nrobots: {count: 20}\ncontroller: {type: faulty, fault: " +
          fault + "}\nengine: {type: " + engine + "}\n",
      "faulty.yaml");
  Replicate replicate(spec, 0);
  try {
    for (int k = 0; k < 10; ++k) replicate.step();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "none";
}

TEST(FaultyController, ACorrectOneRunsOnBothEngines) {
  ASSERT_TRUE(kRegistered);
  EXPECT_EQ(error_of("none"), "none");
  EXPECT_EQ(error_of("none", "box2d"), "none");
}

TEST(FaultyController, ANonFiniteVelocityIsRefusedNamingTheAgentOnBothEngines) {
  for (const char* engine : {"kinematic", "box2d"}) {
    EXPECT_EQ(error_of("nan", engine),
              "controller 'faulty' (replicate 0, deciding at step 5) commanded agent 3 a velocity of (nan, 0) "
              "u/tu, which is not finite")
        << engine;
    EXPECT_THAT(error_of("inf", engine), HasSubstr("agent 3 a velocity of (inf, 0) u/tu"))
        << engine;
  }
}

// 10^6 u/tu moves a body 10^5 u in a step of 0.1, across a 60 x 60 torus many times over.
TEST(FaultyController, ASpeedBeyondWhatTheEnginesResolveIsRefused) {
  for (const char* engine : {"kinematic", "box2d"}) {
    EXPECT_THAT(error_of("fast", engine),
                HasSubstr("commanded agent 3 a velocity of (1e+06, 0) u/tu, which moves it "
                          "farther in one step of 0.1 tu than the engines resolve"))
        << engine;
  }
}

TEST(FaultyController, WhatItThrowsAndASwarmItResizesNameIt) {
  EXPECT_EQ(error_of("throw"),
            "controller 'faulty' (replicate 0, deciding at step 5) failed: no rule for this neighbourhood");
  EXPECT_EQ(error_of("odd"),
            "controller 'faulty' (replicate 0, deciding at step 5) threw something that is not a "
            "std::exception");
  EXPECT_EQ(error_of("resize"),
            "controller 'faulty' (replicate 0, deciding at step 5) changed the number of entries of the "
            "swarm's state (20 agents): a controller keeps one per agent");
}

}  // namespace
}  // namespace swarmagg
