#pragma once
// Figs 20-29: bars per partition, simulation time fraction beside the Soysal model's
// run-averaged probability, original and peripheral. Only the kPartitionBars most likely
// partitions are drawn (N = 20 has 627); the CSV beside the plot holds them all.
#include "reproduce/figure_files.hpp"
#include "reproduce/partition_comparison.hpp"

namespace swarmagg {

inline constexpr int kPartitionBars = 15;

void plot_partitions(const FigureFiles& files, const std::string& title,
                     const PartitionComparison& comparison);

}  // namespace swarmagg
