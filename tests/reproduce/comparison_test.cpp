#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "analysis/partition_comparison.hpp"
#include "reproduce/paper_figures.hpp"

namespace swarmagg {
namespace {

TEST(PaperFigures, EveryPaperWorldFileBelongsToExactlyOneFigure) {
  std::multiset<std::string> listed, files;
  for (const PaperFigure& f : paper_figures()) listed.insert(f.worlds.begin(), f.worlds.end());
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::path(SWARMAGG_SOURCE_DIR) / "worlds" / "paper")) {
    if (entry.path().extension() == ".yaml") files.insert(entry.path().stem().string());
  }
  EXPECT_EQ(listed, files);
}

TEST(PaperFigures, SelectionKeepsMatchingWorldsAndDropsEmptyFigures) {
  const auto selected = select_worlds(paper_figures(), {"collision-speed-1", "full-0.0025"});
  ASSERT_EQ(selected.size(), 2u);
  EXPECT_EQ(selected[0].worlds, (std::vector<std::string>{"collision-speed-1", "collision-speed-10",
                                                          "collision-speed-11"}));
  EXPECT_EQ(selected[1].id, "fig19-full-0.0025");
}

TEST(PartitionComparison, TotalVariationIsHalfTheL1DistanceOverTheUnionOfPartitions) {
  const Distribution a{{"2+1", 0.5}, {"1+1+1", 0.5}};
  const Distribution b{{"2+1", 0.25}, {"3", 0.75}};
  EXPECT_DOUBLE_EQ(total_variation(a, b), 0.5 * (0.25 + 0.5 + 0.75));
  EXPECT_DOUBLE_EQ(total_variation(a, a), 0.0);
}

// The model's own run average (model.csv's run_average rows) is what the simulation is
// compared with; a model.csv without them (an earlier version's) is averaged over its report
// steps by the trapezoid rule.
TEST(PartitionComparison, TheModelsOwnRunAverageIsComparedWhenModelCsvHasIt) {
  const auto folder = std::filesystem::temp_directory_path() /
                      ("swarmagg-partitions-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "partitions.csv")
      << "replicate,partition,time_fraction\n0,2,0.5\n0,1+1,0.5\n";
  const std::string report_steps =
      "model,variant,step,time,quantity,value\n"
      "soysal,original,0,0,partition:1+1,1\nsoysal,original,0,0,partition:2,0\n"
      "soysal,original,10,1,partition:1+1,0\nsoysal,original,10,1,partition:2,1\n"
      "soysal,peripheral,0,0,partition:1+1,1\nsoysal,peripheral,10,1,partition:2,1\n";
  std::ofstream(folder / "model.csv") << report_steps;
  EXPECT_DOUBLE_EQ(compare_partitions(folder).models.front().at("2"), 0.5);
  std::ofstream(folder / "model.csv") << report_steps
                                      << "soysal,original,,,run_average:1+1,0.1\n"
                                         "soysal,original,,,run_average:2,0.9\n";
  const PartitionComparison c = compare_partitions(folder);
  EXPECT_DOUBLE_EQ(c.models.front().at("2"), 0.9);
  EXPECT_DOUBLE_EQ(c.errors.front().error, 0.4);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace swarmagg
