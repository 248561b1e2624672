#include <gtest/gtest.h>

#include <filesystem>
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

}  // namespace
}  // namespace swarmagg
