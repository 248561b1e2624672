#pragma once
// Noise floors (docs/models-returns.md): the error a model variant would show against itself
// when its own process is simulated with the same replicates and run length as the
// simulation it is compared with. An error near its floor is replicate noise; an error many
// times the floor is a miss. Each floor is the mean over kNoiseFloorBatches independent
// batches of `replicates` runs, drawn from the counter-based generator keyed by (seed, stream),
// so it is deterministic.
//  - tv_partition (Soysal): the chain run as a continuous-time Markov process (Gillespie),
//    each replicate's time fractions per partition averaged over the batch, against the
//    chain's own run-averaged distribution (total-variation distance);
//  - rmse_noa (Bayindir): the stochastic model (models/bayindir_stochastic.hpp), the batch's
//    mean NOA against the expected-value series, RMSE over the record grid.
#include <Eigen/Dense>
#include <cstdint>
#include <string>
#include <vector>

#include "models/bayindir_rates.hpp"
#include "models/output_grid.hpp"
#include "models/partition_chain.hpp"

namespace swarmagg {

inline constexpr int kNoiseFloorBatches = 20;
// model.csv's quantity (no step) holding a variant's floor: noise_floor:<metric>.
inline constexpr const char* kNoiseFloorQuantity = "noise_floor:";
inline constexpr const char* kPartitionMetric = "tv_partition";
inline constexpr const char* kNoaMetric = "rmse_noa";

// A stream of draws per variant name (FNV-1a), apart from the model's other streams.
std::uint64_t noise_floor_stream(const std::string& variant);

struct ChainRun {
  Eigen::VectorXd start;    // distribution of the state at `start_step`
  std::int64_t start_step;  // before it the chain sits in all free
  std::int64_t steps;       // the run's length
};

// The fraction of [0, steps] one replicate of `chain` spends in each state.
Eigen::VectorXd chain_time_fractions(const PartitionChain& chain, const ChainRun& run,
                                     std::uint64_t seed, std::uint64_t replicate,
                                     std::uint64_t stream);

double partition_noise_floor(const PartitionChain& chain, const ChainRun& run,
                             const Eigen::VectorXd& run_average, int replicates, std::uint64_t seed,
                             std::uint64_t stream, int batches = kNoiseFloorBatches);

// Against the expected series from `start` (models/bayindir_expected.hpp), which runs beside
// the batches' replicates, so that no series is held. `progress` counts the replicates'
// steps.
double noa_noise_floor(const BayindirRates& rates, const std::vector<std::int64_t>& grid,
                       const std::vector<double>& start, int replicates, std::uint64_t seed,
                       std::uint64_t stream, int batches = kNoiseFloorBatches,
                       const WalkProgress& progress = {});

}  // namespace swarmagg
