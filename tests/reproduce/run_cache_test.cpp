// A cached run folder is reused only when this build ran the same world and finished it to the
// end, model errors included.
#include "reproduce/run_cache.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "config/world_loader.hpp"
#include "run/run_folder.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

// A folder with every file run_is_reusable looks at, summary.json as given.
void lay_out(const std::filesystem::path& folder, const WorldSpec& spec,
             const std::string& summary) {
  write(folder / "world.resolved.yaml", resolved_world_text(spec));
  for (const char* file : {"timeseries.csv", "model.csv", "rates.csv"}) write(folder / file, "x\n");
  write(folder / "summary.json", summary);
}

TEST(RunCache, ReusesOnlyAFolderWhoseSummaryHoldsItsModelErrors) {
  const WorldSpec spec = load_world_text("name: cached\n", "cached.yaml");
  testing::ScratchDir dir("run-cache");
  lay_out(dir.path(), spec, R"({"model_errors": []})");
  EXPECT_TRUE(run_is_reusable(spec, dir.path()));
  lay_out(dir.path(), spec, R"({"replicates": []})");
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
}

TEST(RunCache, DoesNotReuseAnotherWorldsRun) {
  const WorldSpec spec = load_world_text("name: cached\n", "cached.yaml");
  const WorldSpec other = load_world_text("name: cached\nrobots: {count: 7}\n", "cached.yaml");
  testing::ScratchDir dir("run-cache-other");
  lay_out(dir.path(), other, R"({"model_errors": []})");
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
}

// After an upgrade the same world file can give other outputs (an engine fix moves them): a
// run another swarmagg version or commit made is run again.
TEST(RunCache, DoesNotReuseARunAnotherBuildMade) {
  const WorldSpec spec = load_world_text("name: cached\n", "cached.yaml");
  testing::ScratchDir dir("run-cache-build");
  lay_out(dir.path(), spec, R"({"model_errors": []})");
  std::string text = resolved_world_text(spec);
  ASSERT_TRUE(text.starts_with("# Resolved by swarmagg "));
  text.replace(0, text.find('\n'), "# Resolved by swarmagg 0.0.1 (0123abc); every key is shown.");
  write(dir.path() / "world.resolved.yaml", text);
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
}

}  // namespace
}  // namespace swarmagg
