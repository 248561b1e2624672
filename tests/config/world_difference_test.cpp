#include "config/world_difference.hpp"

#include <gtest/gtest.h>

#include "config/world_loader.hpp"
#include "config/world_writer.hpp"

namespace swarmagg {
namespace {

WorldSpec demo(const std::vector<std::string>& overrides = {}) {
  return load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml", overrides);
}

TEST(WorldDifference, RunLengthSeedAndModelKeysLeaveTheSameSystem) {
  const std::string there = world_to_yaml(demo());
  EXPECT_TRUE(
      system_differences(there, demo({"run.duration=5", "run.seed=9",
                                      "model.initial_state=all_searching", "render.every=10"}))
          .empty());
}

TEST(WorldDifference, NamesEachSystemKeyThatDiffersWithBothValues) {
  const std::string there = world_to_yaml(demo());
  const std::vector<std::string> differences =
      system_differences(there, demo({"robots.count=10", "controller.p_leave=0.002",
                                      "engine.dt=0.05", "arena.topology=walls"}));
  ASSERT_EQ(differences.size(), 4u);
  EXPECT_EQ(differences[0], "arena.topology: torus there, walls here");
  EXPECT_EQ(differences[1], "robots.count: 60 there, 10 here");
  EXPECT_EQ(differences_text(differences),
            "arena.topology: torus there, walls here; robots.count: 60 there, 10 here; "
            "controller.p_leave: 0.001 there, 0.002 here; and 1 more");
}

TEST(WorldDifference, GivenPositionsAndUnreadableTextsDiffer) {
  WorldSpec placed = demo({"robots.count=2"});
  placed.robots.placement = {{1, 1, 0}, {5, 1, 0}};
  const std::vector<std::string> differences =
      system_differences(world_to_yaml(demo({"robots.count=2"})), placed);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_EQ(differences[0].rfind("robots.placement: random there, [", 0), 0u) << differences[0];
  EXPECT_EQ(system_differences("arena: [unclosed", demo()),
            std::vector<std::string>{"the world text: unreadable"});
}

}  // namespace
}  // namespace swarmagg
