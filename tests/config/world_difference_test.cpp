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

// A world.resolved.yaml of an older version lacks keys added since, and a hand-written one
// spells numbers its own way: read as worlds, they are the same system.
TEST(WorldDifference, MissingDefaultsAndOtherSpellingsAreTheSameSystem) {
  std::string older = world_to_yaml(demo());
  const std::size_t contact = older.find("  contact: slide\n");
  ASSERT_NE(contact, std::string::npos);
  older.erase(contact, std::string("  contact: slide\n").size());
  EXPECT_TRUE(system_differences(older, demo()).empty());
  const std::string spelt =
      "name: demo\narena: {width: 120.0, height: 1.2e2}\nrobots: {count: 60, radius: 1.0, "
      "detection_radius: 4, speed: 1}\ncontroller: {type: bayindir, p_leave: 1e-3, join: true, "
      "leave: true, leave_timeout: 10}\n";
  EXPECT_TRUE(system_differences(spelt, demo()).empty())
      << differences_text(system_differences(spelt, demo()));
}

TEST(WorldDifference, Box2dSettingsMatterOnlyToBox2dWorlds) {
  const std::string there = world_to_yaml(demo());
  EXPECT_TRUE(system_differences(there, demo({"engine.box2d.velocity_iterations=4"})).empty());
  const std::string box2d = world_to_yaml(demo({"engine.type=box2d"}));
  EXPECT_EQ(
      system_differences(box2d, demo({"engine.type=box2d", "engine.box2d.velocity_iterations=4"})),
      std::vector<std::string>{"engine.box2d.velocity_iterations: 8 there, 4 here"});
}

TEST(WorldDifference, GivenPositionsAndUnreadableTextsDiffer) {
  WorldSpec placed = demo({"robots.count=2"});
  placed.robots.placement = {{1, 1, 0}, {5, 1, 0}};
  const std::vector<std::string> differences =
      system_differences(world_to_yaml(demo({"robots.count=2"})), placed);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_EQ(differences[0].rfind("robots.placement: random there, [", 0), 0u) << differences[0];
  for (const char* unreadable : {"arena: [unclosed", "", "just text"}) {
    EXPECT_EQ(system_differences(unreadable, demo()),
              std::vector<std::string>{"the world text: unreadable"})
        << unreadable;
  }
}

// A model's errors against a run depend on the run's steps, recorded rows and replicates, not
// on how its length is spelt: 100 and 100.01 tu at dt 0.1 are the same 1,000 steps.
TEST(WorldDifference, AMeasuredRunIsTheSameRunWhenItRunsTheSameSteps) {
  const std::string there = world_to_yaml(demo({"run.duration=100"}));
  EXPECT_TRUE(measured_run_differences(there, demo({"run.duration=100.01", "run.seed=4"})).empty());
  EXPECT_EQ(
      measured_run_differences(there, demo({"run.duration=200"})),
      std::vector<std::string>{"run.duration / engine.dt: 1000 steps there, 2000 steps here"});
  EXPECT_EQ(measured_run_differences(there, demo({"run.duration=100", "run.replicates=3"})),
            std::vector<std::string>{"run.replicates: 4 there, 3 here"});
  EXPECT_EQ(measured_run_differences(there, demo({"run.duration=100", "engine.dt=0.05"})).size(),
            2u);
}

}  // namespace
}  // namespace swarmagg

namespace swarmagg {
namespace {

// What reproduce records in summary.json as the overrides of a paper world: every key the
// world as run changed, with the value it ran with, in the resolved text's order; not a name.
TEST(ChangedKeys, NamesEveryChangedKeyWithItsNewValue) {
  const WorldSpec file = load_world_text("name: paper\nrun: {duration: 1000}\n", "paper.yaml");
  WorldSpec run = file;
  EXPECT_TRUE(changed_keys(file, run).empty());
  run.name = "paper-timeout-20";
  run.run.duration = 40;
  run.controller.compaction.enabled = false;
  EXPECT_EQ(changed_keys(file, run),
            (std::vector<std::string>{"controller.compaction.enabled=false", "run.duration=40"}));
}

}  // namespace
}  // namespace swarmagg
