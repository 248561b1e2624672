#pragma once
// The Soysal partition model of one world and leaving variant: the distribution over
// partitions at the steps of sparse_grid (from all agents free) and, when agents can leave,
// the stationary distribution; with their expected NOA, free agents ("searching": the model
// does not tell GO, APPROACH and LEAVE apart) and largest aggregate.
#include "config/world_spec.hpp"
#include "models/model_series.hpp"

namespace swarmagg {

// Dense transient computation: above this many partitions (N >= 26) it would take minutes.
inline constexpr int kLargestPartitionChain = 2000;
// About this many log-spaced and as many evenly spaced reporting steps.
inline constexpr int kPartitionReportPoints = 50;

// Throws InputError when N has more than kLargestPartitionChain partitions.
VariantPrediction soysal_prediction(const WorldSpec& world, LeavingVariant variant);

std::string leaving_variant_name(LeavingVariant variant);

}  // namespace swarmagg
