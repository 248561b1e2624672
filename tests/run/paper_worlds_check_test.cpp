// The paper worlds run with every invariant checked after every step (`run --check`), short.
// The checks include sleep's: the kinematic engine also resolves each step in full and fails
// on any agent that slept though it would have moved, so these runs show on the worlds users
// run that sleep changes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {
namespace {

struct CheckedWorld {
  std::string file;
  std::vector<std::string> overrides;
};

TEST(PaperWorldsCheck, RunWithEveryInvariantChecked) {
  const std::vector<CheckedWorld> worlds = {
      {"soysal-5-constant", {"run.duration=3000", "controller.p0=0.002"}},
      {"soysal-10-constant", {"run.duration=2000", "controller.p0=0.0005"}},
      {"soysal-20-constant", {"run.duration=1500", "controller.p0=0.0002"}},
      {"full-0.0025", {"run.duration=300"}},
      {"full-0.0025", {"run.duration=200", "arena.topology=walls"}},
      {"creation-growing-160", {"run.duration=200"}},
  };
  for (const CheckedWorld& world : worlds) {
    std::vector<std::string> overrides = {"run.replicates=2", "run.threads=2"};
    overrides.insert(overrides.end(), world.overrides.begin(), world.overrides.end());
    const WorldSpec spec = load_world(
        std::string(SWARMAGG_SOURCE_DIR) + "/worlds/paper/" + world.file + ".yaml", overrides);
    RunOptions options;
    options.check = true;
    EXPECT_NO_THROW(run_world(spec, options)) << world.file;
  }
}

}  // namespace
}  // namespace swarmagg
