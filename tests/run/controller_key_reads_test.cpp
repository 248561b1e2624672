// A shared controller key that a controller's registration does not list is left out of its
// resolved world (world.resolved.yaml, `validate`) and refused in its world files and from
// --set, but `reproduce --set` applies one override to worlds of every controller. It must
// then not act on its runs either, or the resolved world would not load back as the world
// that ran: controller.tumble once turned Soysal searchers through `--set` while their
// registration left it out. Each registered controller is run with every shared key it does
// not list set away from its default, and must run exactly as without it.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "config/controller_catalog.hpp"
#include "config/world_loader.hpp"
#include "config/world_override.hpp"
#include "run/replicate.hpp"
#include "run/state_hash.hpp"

namespace swarmagg {
namespace {

// A value away from the default for every shared controller key (nested blocks by their
// keys); the test fails when a new shared key has none, so that it is covered too.
const std::map<std::string, std::string>& changed_values() {
  static const std::map<std::string, std::string> values = {
      {"controller.approach_radius", "9"},
      {"controller.collision_mode", "paper"},
      {"controller.compaction.enabled", "false"},
      {"controller.compaction.gain", "0.3"},
      {"controller.compaction.spacing", "2.5"},
      {"controller.compaction.tolerance", "0.4"},
      {"controller.isolated_wait", "stay"},
      {"controller.join", "false"},
      {"controller.leave", "false"},
      {"controller.leave_law", "inverse"},
      {"controller.leave_size", "neighbours"},
      {"controller.leave_timeout", "3"},
      {"controller.p0", "0.3"},
      {"controller.p_leave", "0.3"},
      {"controller.tumble", "0.3"},
  };
  return values;
}

bool is_shared_controller_key(const WorldKey& key) {
  return key.path.starts_with("controller.") && key.path != "controller.type" &&
         key.controller.empty() && key.read != nullptr;
}

std::uint64_t hash_after_steps(const std::string& type, const std::vector<std::string>& extra) {
  // The demo world is sparse enough that Soysal searchers perceive nobody for a while.
  WorldSpec spec = load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml",
                              {"controller.type=" + type, "run.seed=5"});
  // Applied as `reproduce --set` applies them: the loader refuses an unlisted key from --set.
  for (const WorldOverride& o : parse_overrides(extra)) apply_override(spec, o);
  Replicate replicate(spec, 0);
  for (int step = 0; step < 400; ++step) replicate.step();
  return state_hash(replicate);
}

TEST(ControllerKeyReads, EverySharedControllerKeyHasAChangedValue) {
  for (const WorldKey& key : world_keys()) {
    if (!is_shared_controller_key(key)) continue;
    EXPECT_TRUE(changed_values().contains(key.path)) << key.path;
  }
}

TEST(ControllerKeyReads, KeysAControllerDoesNotListLeaveItsRunsAsTheyAre) {
  int checked = 0;
  for (const ControllerCatalogEntry& entry : controller_catalog()) {
    const std::uint64_t plain = hash_after_steps(entry.type, {});
    for (const auto& [path, value] : changed_values()) {
      const auto& listed = entry.shared_keys;
      if (std::find(listed.begin(), listed.end(), path) != listed.end()) continue;
      EXPECT_EQ(hash_after_steps(entry.type, {path + "=" + value}), plain)
          << "controller type '" << entry.type << "' does not list " << path
          << " among its keys, but setting it changed the run";
      ++checked;
    }
  }
  EXPECT_GT(checked, 10);  // the catalog's controllers leave keys out: the test looked
}

}  // namespace
}  // namespace swarmagg
