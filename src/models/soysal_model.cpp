#include "models/soysal_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "core/errors.hpp"
#include "models/chain_distribution.hpp"
#include "models/initial_state.hpp"
#include "models/noise_floor.hpp"
#include "models/output_grid.hpp"
#include "models/partition_chain.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

namespace {

// Per-state values of the derived quantities, so that expectations are dot products.
struct StateObservables {
  Eigen::VectorXd noa, free, largest;
};

StateObservables observables_of(const std::vector<Partition>& states) {
  const auto n = static_cast<Eigen::Index>(states.size());
  StateObservables values{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    values.noa(i) = aggregate_count(states[i]);
    values.free(i) = free_agents(states[i]);
    values.largest(i) = largest_aggregate(states[i]);
  }
  return values;
}

ModelRow expected_row(const Eigen::RowVectorXd& distribution, const StateObservables& values,
                      int agents, std::int64_t step) {
  ModelRow row;
  row.step = step;
  row.noa = distribution.dot(values.noa);
  row.searching = distribution.dot(values.free);
  row.waiting = agents - *row.searching;
  row.largest = distribution.dot(values.largest);
  return row;
}

void add_stationary(const PartitionChain& chain, const StateObservables& values,
                    const Eigen::VectorXd& stationary, VariantPrediction& prediction) {
  for (std::size_t i = 0; i < chain.states.size(); ++i) {
    prediction.extra.push_back({"stationary:" + partition_label(chain.states[i]), std::nullopt,
                                stationary(static_cast<Eigen::Index>(i))});
  }
  prediction.extra.push_back({"stationary_noa", std::nullopt, stationary.dot(values.noa)});
  prediction.extra.push_back({"stationary_searching", std::nullopt, stationary.dot(values.free)});
  prediction.extra.push_back({"stationary_largest", std::nullopt, stationary.dot(values.largest)});
}

// Independent Poisson counts of aggregates of each size, over the chain's partitions.
Eigen::VectorXd first_decision_distribution(const PartitionChain& chain,
                                            const std::vector<double>& start) {
  const auto n = static_cast<Eigen::Index>(chain.states.size());
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    std::map<int, int> counts;
    for (const int part : chain.states[static_cast<std::size_t>(i)]) {
      if (part >= 2) ++counts[part];
    }
    double log_weight = 0.0;
    for (std::size_t m = 2; m < start.size(); ++m) {
      const double mean = start[m];
      const int k = counts.contains(static_cast<int>(m)) ? counts[static_cast<int>(m)] : 0;
      if (mean <= 0.0) {
        if (k > 0) log_weight = -std::numeric_limits<double>::infinity();
        continue;
      }
      log_weight += -mean + k * std::log(mean) - std::lgamma(k + 1.0);
    }
    for (const auto& [part, k] : counts) {
      if (part >= static_cast<int>(start.size()) && k > 0)
        log_weight = -std::numeric_limits<double>::infinity();
    }
    weights(i) = std::exp(log_weight);
  }
  const double total = weights.sum();
  if (!(total > 0.0)) return Eigen::VectorXd::Unit(n, chain.all_free);
  return weights / total;
}

// The sampled partitions' probabilities, over the chain's states: the partitions reachable
// from all free. A sampled partition outside them (possible only where some pair-up or join
// rate is 0) is left out, and the rest renormalised.
Eigen::VectorXd sampled_first_decision_distribution(const PartitionChain& chain,
                                                    const std::map<Partition, double>& sampled) {
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.states.size()));
  for (std::size_t i = 0; i < chain.states.size(); ++i) {
    const auto found = sampled.find(chain.states[i]);
    if (found != sampled.end()) weights(static_cast<Eigen::Index>(i)) = found->second;
  }
  const double total = weights.sum();
  if (!(total > 0.0)) return Eigen::VectorXd::Unit(weights.size(), chain.all_free);
  return weights / total;
}

// by_size[m]: the expected number of aggregates of size m under `distribution`.
std::vector<double> expected_sizes(const std::vector<Partition>& states,
                                   const Eigen::RowVectorXd& distribution, int agents) {
  std::vector<double> by_size(static_cast<std::size_t>(agents) + 1, 0.0);
  for (std::size_t i = 0; i < states.size(); ++i) {
    for (const int part : states[i]) {
      if (part >= 2) by_size[part] += distribution(static_cast<Eigen::Index>(i));
    }
  }
  return by_size;
}

// The distribution averaged over the run, by the trapezoid rule over the steps of `grid`
// (integration_grid's, fine at the start where the chain moves fastest): what the
// simulation's time fractions are compared with (analysis/partition_comparison.hpp).
Eigen::VectorXd run_average(const Eigen::MatrixXd& distributions,
                            const std::vector<std::int64_t>& grid) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(distributions.cols());
  for (std::size_t j = 1; j < grid.size(); ++j) {
    const auto row = static_cast<Eigen::Index>(j);
    area += 0.5 * static_cast<double>(grid[j] - grid[j - 1]) *
            (distributions.row(row) + distributions.row(row - 1)).transpose();
  }
  const double span = static_cast<double>(grid.back() - grid.front());
  if (span > 0.0) return area / span;
  return distributions.row(distributions.rows() - 1).transpose();
}

// The chain's distribution at each step of `grid`, from `run`'s start: all free at step 0,
// and from step run.start_step on the start distribution walked forward.
Eigen::MatrixXd distributions_at(const PartitionChain& chain, const ChainRun& run,
                                 const std::vector<std::int64_t>& grid,
                                 const std::optional<Eigen::VectorXd>& stationary,
                                 const WalkProgress& check) {
  if (run.start_step == 0)
    return transient_distributions(chain.generator, run.start, grid, stationary, check);
  std::vector<std::int64_t> after_first(grid.size());
  for (std::size_t j = 0; j < grid.size(); ++j)
    after_first[j] = std::max<std::int64_t>(0, grid[j] - run.start_step);
  Eigen::MatrixXd distributions =
      transient_distributions(chain.generator, run.start, after_first, stationary, check);
  for (std::size_t j = 0; j < grid.size(); ++j) {
    if (grid[j] == 0) {
      distributions.row(static_cast<Eigen::Index>(j)) =
          Eigen::RowVectorXd::Unit(distributions.cols(), chain.all_free);
    }
  }
  return distributions;
}

}  // namespace

std::string leaving_variant_name(LeavingVariant variant) {
  return variant == LeavingVariant::Original ? "original" : "peripheral";
}

VariantPrediction soysal_prediction(const WorldSpec& world, LeavingVariant variant,
                                    const PlacementSample* sample) {
  return soysal_prediction(world, soysal_rates(world, variant), leaving_variant_name(variant),
                           start_aggregates(world, nullptr, sample),
                           start_partitions(world, sample));
}

void check_partition_chain_size(const WorldSpec& world) {
  const int agents = world.robots.count;
  if (const long long states = partition_count(agents); states > kLargestPartitionChain) {
    const bool beyond = states == std::numeric_limits<long long>::max();
    throw InputError("model: the partition model of " + std::to_string(agents) + " agents has " +
                     (beyond ? "more than " : "") + std::to_string(states) + " states; at most " +
                     std::to_string(kLargestPartitionChain) + " (N <= 30) are supported");
  }
}

VariantPrediction soysal_prediction(const WorldSpec& world, const SoysalRates& rates,
                                    const std::string& variant, const std::vector<double>& start,
                                    const std::map<Partition, double>* start_partitions,
                                    const WalkProgress& check) {
  const bool sampled = start_partitions && !start_partitions->empty();
  check_partition_chain_size(world);
  const int agents = world.robots.count;
  const PartitionChain chain = build_partition_chain(rates);
  VariantPrediction prediction{.model = "soysal", .variant = variant};
  const StateObservables values = observables_of(chain.states);
  const std::vector<std::int64_t> grid = sparse_grid(world, kPartitionReportPoints);
  std::optional<Eigen::VectorXd> stationary;
  if (chain.recurrent) stationary = stationary_distribution(chain.generator, check);
  ChainRun run{.start = Eigen::VectorXd::Unit(static_cast<Eigen::Index>(chain.states.size()),
                                              chain.all_free),
               .start_step = 0,
               .steps = world.steps()};
  if (!start.empty() || sampled) {
    // Step 0 is all free; from step 1 on the chain runs from the first decision's distribution.
    run.start = sampled ? sampled_first_decision_distribution(chain, *start_partitions)
                        : first_decision_distribution(chain, start);
    run.start_step = 1;
  }
  const Eigen::MatrixXd distributions = distributions_at(chain, run, grid, stationary, check);
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const Eigen::RowVectorXd distribution = distributions.row(static_cast<Eigen::Index>(j));
    prediction.series.push_back(expected_row(distribution, values, agents, grid[j]));
    for (std::size_t i = 0; i < chain.states.size(); ++i) {
      prediction.extra.push_back({"partition:" + partition_label(chain.states[i]), grid[j],
                                  distribution(static_cast<Eigen::Index>(i))});
    }
  }
  add_size_distribution(
      prediction.extra, grid.back(),
      expected_sizes(chain.states, distributions.row(distributions.rows() - 1), agents));
  if (stationary) add_stationary(chain, values, *stationary, prediction);
  const std::vector<std::int64_t> fine = integration_grid(world, kPartitionAveragePoints);
  const Eigen::VectorXd average =
      run_average(distributions_at(chain, run, fine, stationary, check), fine);
  for (std::size_t i = 0; i < chain.states.size(); ++i) {
    prediction.extra.push_back({kRunAverageQuantity + partition_label(chain.states[i]),
                                std::nullopt, average(static_cast<Eigen::Index>(i))});
  }
  prediction.extra.push_back({std::string(kNoiseFloorQuantity) + kPartitionMetric, std::nullopt,
                              partition_noise_floor(chain, run, average, world.run.replicates,
                                                    world.run.seed, noise_floor_stream(variant))});
  return prediction;
}

}  // namespace swarmagg
