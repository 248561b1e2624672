// A cached run folder is reused only when this build ran the same world and finished it to the
// end, model errors included.
#include "reproduce/run_cache.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "config/world_loader.hpp"
#include "output/timeseries_csv.hpp"
#include "run/run_folder.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

// 2 replicates of 10 steps recorded every 4th step: steps 0, 4, 8 and 10, so 9 lines.
const char* kCached = "name: cached\nrun: {duration: 1, replicates: 2, record_every: 4}\n";

// The rows of replicate r at `step`, `noa` aggregates and every other count 0.
std::string row(int replicate, int step, const std::string& noa = "0") {
  return std::to_string(replicate) + "," + std::to_string(step) + "," +
         std::to_string(step / 10.0) + "," + noa + ",0,0,0,0,0,0,0,0,0,0\n";
}
const std::string kCachedRows = std::string(kTimeseriesHeader) + "\n" + row(0, 0) + row(0, 4) +
                                row(0, 8) + row(0, 10) + row(1, 0) + row(1, 4) + row(1, 8) +
                                row(1, 10);

// A folder with every file run_is_reusable looks at, summary.json as given.
void lay_out(const std::filesystem::path& folder, const WorldSpec& spec,
             const std::string& summary) {
  write(folder / "world.resolved.yaml", resolved_world_text(spec));
  write(folder / "timeseries.csv", kCachedRows);
  for (const char* file : {"model.csv", "rates.csv", "partitions.csv"}) write(folder / file, "x\n");
  write(folder / "summary.json", summary);
}

TEST(RunCache, ReusesOnlyAFolderWhoseSummaryHoldsItsModelErrors) {
  const WorldSpec spec = load_world_text(kCached, "cached.yaml");
  testing::ScratchDir dir("run-cache");
  lay_out(dir.path(), spec, R"({"model_errors": []})");
  EXPECT_TRUE(run_is_reusable(spec, dir.path()));
  lay_out(dir.path(), spec, R"({"replicates": []})");
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
}

TEST(RunCache, DoesNotReuseAnotherWorldsRun) {
  const WorldSpec spec = load_world_text(kCached, "cached.yaml");
  const WorldSpec other =
      load_world_text(std::string(kCached) + "robots: {count: 7}\n", "cached.yaml");
  testing::ScratchDir dir("run-cache-other");
  lay_out(dir.path(), other, R"({"model_errors": []})");
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
}

// After an upgrade the same world file can give other outputs (an engine fix moves them): a
// run another swarmagg version or commit made is run again.
TEST(RunCache, DoesNotReuseARunAnotherBuildMade) {
  const WorldSpec spec = load_world_text(kCached, "cached.yaml");
  testing::ScratchDir dir("run-cache-build");
  lay_out(dir.path(), spec, R"({"model_errors": []})");
  std::string text = resolved_world_text(spec);
  ASSERT_TRUE(text.starts_with("# Resolved by swarmagg "));
  text.replace(0, text.find('\n'), "# Resolved by swarmagg 0.0.1 (0123abc); every key is shown.");
  write(dir.path() / "world.resolved.yaml", text);
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
}

// A file cut short or edited since, or a Soysal run's missing partitions, is not the run the
// folder's other files describe: REPORT.md read the shortened rows as the run.
TEST(RunCache, DoesNotReuseAFolderMissingRowsOrPartitions) {
  const WorldSpec spec = load_world_text(kCached, "cached.yaml");
  testing::ScratchDir dir("run-cache-rows");
  lay_out(dir.path(), spec, R"({"model_errors": []})");
  ASSERT_TRUE(run_is_reusable(spec, dir.path()));
  write(dir.path() / "timeseries.csv", kCachedRows.substr(0, kCachedRows.rfind(row(1, 8))));
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
  write(dir.path() / "timeseries.csv", kCachedRows + "1");  // a line cut mid-way
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
  // As many lines, one edited: a NOA no run of the world can have (REPORT.md's RMSE read it).
  std::string edited = kCachedRows;
  edited.replace(edited.find(row(1, 4)), row(1, 4).size(), row(1, 4, "999"));
  write(dir.path() / "timeseries.csv", edited);
  EXPECT_FALSE(run_is_reusable(spec, dir.path()));
  write(dir.path() / "timeseries.csv", kCachedRows);
  ASSERT_TRUE(run_is_reusable(spec, dir.path()));
  const WorldSpec soysal = load_world_text(
      std::string(kCached) + "robots: {count: 5}\ncontroller: {type: soysal}\n", "cached.yaml");
  lay_out(dir.path(), soysal, R"({"model_errors": []})");
  ASSERT_TRUE(run_is_reusable(soysal, dir.path()));
  std::filesystem::remove(dir.path() / "partitions.csv");
  EXPECT_FALSE(run_is_reusable(soysal, dir.path()));
}

}  // namespace
}  // namespace swarmagg
