#pragma once
// Simulated partition time fractions against the Soysal model variants (Figs 20-29), read
// from a run folder: partitions.csv (time fraction per replicate) and model.csv. The
// simulation measures the fraction of the run spent in each partition, transient included,
// so the model is compared through the same quantity: its partition probabilities averaged
// over the run (trapezoid rule on the model's report steps). The error is the
// total-variation distance, half the sum of absolute differences.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "analysis/variant_error.hpp"

namespace swarmagg {

using Distribution = std::map<std::string, double>;  // partition ("3+1+1") -> probability

const std::vector<std::string>& partition_variants();  // original, peripheral

struct PartitionComparison {
  Distribution simulation;  // mean time fraction across replicates
  // run-averaged, in partition_variants() order, then kReturnsVariant and kMeasuredVariant
  // when model.csv has them
  std::vector<Distribution> models;
  std::vector<Distribution> stationary;
  std::vector<VariantError> errors;  // total-variation distance per variant
  double spread = 0.0;               // the replicates' own (analysis/replicate_spread.hpp)
};

double total_variation(const Distribution& a, const Distribution& b);

// partitions.csv's time fractions, one distribution per replicate (in replicate order), and
// their mean over the replicates.
std::vector<Distribution> replicate_partitions(const std::filesystem::path& partitions_csv);
Distribution mean_partitions(const std::vector<Distribution>& replicates);

// Without model.csv in the folder, models, stationary and errors stay empty.
PartitionComparison compare_partitions(const std::filesystem::path& run_folder);

}  // namespace swarmagg
