#include "compare/engine_comparison.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "compare/compare_plots.hpp"
#include "config/world_loader.hpp"
#include "plot/gnuplot.hpp"

namespace swarmagg {
namespace {

WorldSpec tiny_world() {
  return load_world_text(R"(
name: tiny
arena: {width: 40, height: 40}
robots: {count: 16}
controller: {type: bayindir, p_leave: 0.005, leave_timeout: 5}
run: {duration: 60, replicates: 3, record_every: 20, seed: 5}
)",
                         "tiny");
}

TEST(EngineComparison, RunsBothEnginesWithTheSameSeeds) {
  const EngineComparison result = compare_engines(tiny_world());
  EXPECT_EQ(result.kinematic.spec.engine.type, EngineType::Kinematic);
  EXPECT_EQ(result.box2d.spec.engine.type, EngineType::Box2D);
  ASSERT_EQ(result.box2d.run.replicates.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(result.kinematic.run.replicates[k].seed, result.box2d.run.replicates[k].seed);
  }
  EXPECT_EQ(result.stats.a.label, "kinematic");
  EXPECT_EQ(result.stats.b.label, "box2d");
}

TEST(EngineComparison, WritesTheFolder) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot not installed";
  const EngineComparison result = compare_engines(tiny_world());
  const auto out = std::filesystem::temp_directory_path() / "swarmagg-compare-test";
  std::filesystem::remove_all(out);
  write_compare_folder(result.kinematic, result.box2d, result.stats, out);
  for (const char* name :
       {"summary.txt", "compare.json", "noa.csv", "noa.gp", "noa.png", "final_noa.csv", "sizes.csv",
        "final.gp", "final.png", "escape_rate.csv", "escape_rate.gp", "escape_rate.png",
        "kinematic/timeseries.csv", "box2d/timeseries.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  }
  std::filesystem::remove_all(out);
}

TEST(ComparePlots, HistogramCountsEachValueOfEachArm) {
  EXPECT_EQ(histogram_csv("size", "a", {2, 2, 3}, "b", {3, 5}), "size,a,b\n2,2,0\n3,1,1\n5,0,1\n");
}

}  // namespace
}  // namespace swarmagg
