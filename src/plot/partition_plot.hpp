#pragma once
// Bars per partition, the simulation's time fraction beside the run-averaged probability
// of each Soysal model variant the comparison holds (none for a run without model.csv):
// reproduce's Figs 20-29 and a Soysal run folder's partitions.png. Only the kPartitionBars
// most likely partitions are drawn (N = 20 has 627); the CSV beside the plot holds them all.
#include "analysis/partition_comparison.hpp"
#include "plot/figure_files.hpp"

namespace swarmagg {

inline constexpr int kPartitionBars = 15;

void plot_partitions(const FigureFiles& files, const std::string& title,
                     const PartitionComparison& comparison);

}  // namespace swarmagg
