#pragma once
// The Soysal partition model of one world and leaving variant: the distribution over
// partitions at the steps of sparse_grid (from all agents free) and, when agents can leave,
// the stationary distribution; with their expected NOA, free agents ("searching": the model
// does not tell GO, APPROACH and LEAVE apart) and largest aggregate.
#include <map>

#include "config/world_spec.hpp"
#include "models/initial_state.hpp"
#include "models/model_series.hpp"
#include "models/output_grid.hpp"
#include "models/partitions.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

// The stationary distribution is a dense O(n^3) elimination with n^2 doubles: N = 30 (5604
// partitions) takes ~5 s and 250 MB; each further agent multiplies that by ~1.2^3 and 1.2^2.
inline constexpr int kLargestPartitionChain = 6000;
// About this many log-spaced and as many evenly spaced reporting steps.
inline constexpr int kPartitionReportPoints = 50;
// Steps (log-spaced and evenly spaced, each) over which the run-averaged distribution is
// integrated, written to model.csv as "run_average:<partition>" rows without a step.
inline constexpr int kPartitionAveragePoints = 200;
inline constexpr const char* kRunAverageQuantity = "run_average:";

// The first refusal of soysal_prediction, alone: InputError when N has more than
// kLargestPartitionChain partitions.
void check_partition_chain_size(const WorldSpec& world);

// Throws InputError when N has more than kLargestPartitionChain partitions. The chain starts
// from all free (step 0); with `start` (expected aggregates [m] after the first decision,
// models/initial_state.hpp) the distribution at step 1 is that of independent Poisson
// counts of aggregates of each size with those means (restricted to partitions of N, and
// renormalized), and the chain runs from there.
// With `start_partitions` (PlacementSample::partitions: the probability of each partition
// after the first decision, as sampled) the chain starts from that distribution exactly
// instead (`start` is then not read). `check` is called with 0 now and then (the caller's
// check for Ctrl-C: the chain of N = 30 takes seconds).
VariantPrediction soysal_prediction(const WorldSpec& world, const SoysalRates& rates,
                                    const std::string& variant,
                                    const std::vector<double>& start = {},
                                    const std::map<Partition, double>* start_partitions = nullptr,
                                    const WalkProgress& check = {});
// The world's own rates and start (model.initial_state, not measured; `sample` as for
// start_aggregates).
VariantPrediction soysal_prediction(const WorldSpec& world, LeavingVariant variant,
                                    const PlacementSample* sample = nullptr);

std::string leaving_variant_name(LeavingVariant variant);

}  // namespace swarmagg
