#include "models/predictions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <span>

#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "models/bayindir_expected.hpp"
#include "models/bayindir_stochastic.hpp"
#include "models/initial_state.hpp"
#include "models/measured_rates.hpp"
#include "models/noise_floor.hpp"
#include "models/output_grid.hpp"
#include "models/return_probability.hpp"
#include "models/returns_rates.hpp"
#include "models/sample_statistics.hpp"
#include "models/soysal_model.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

namespace {

constexpr CreationVariant kCreationVariants[] = {CreationVariant::Original,
                                                 CreationVariant::Collision};

std::string creation_variant_name(CreationVariant variant) {
  return variant == CreationVariant::Original ? "original" : "collision";
}

// Streams of the measured and returns variants' stochastic draws (the creation variants
// use 0 and 1).
constexpr std::uint64_t kMeasuredStream = 2;
constexpr std::uint64_t kReturnsStream = 3;
// Mean neighbours within s per agent above which placement_second_order is off by more than
// a tenth in the triples (docs/models.md, "Where the models start").
constexpr double kSecondOrderNeighbours = 0.1;

// The returns variant matters only where aggregates lose leavers.
bool knows_returns(const WorldSpec& world) {
  const ControllerRules rules = controller_rules(world);
  return rules.leaves && rules.model != ModelFamily::Encounters;
}

// The steps the Bayindir variants report at, one list for all of them.
using SharedGrid = std::shared_ptr<const std::vector<std::int64_t>>;

// An expected-value variant with its size distribution at the last step and, where it
// forms aggregates, its NOA noise floor (models/noise_floor.hpp); then `notes`.
PendingVariant bayindir_expected(const WorldSpec& world, const BayindirRates& rates,
                                 const std::string& variant, const SharedGrid& grid,
                                 const std::vector<double>& start,
                                 const std::vector<TidyValue>& notes = {}) {
  const int replicates = world.run.replicates;
  const std::uint64_t seed = world.run.seed;
  const double floor_replicates = rates.forms_aggregates ? replicates * kNoiseFloorBatches : 0.0;
  PendingVariant pending{
      .header = {.model = "bayindir", .variant = variant},
      .walk_rows_work = static_cast<double>(grid->back()) * (1.0 + floor_replicates)};
  pending.walk_rows = [=](const RowVisitor& visit, const WalkProgress& progress) {
    BayindirState last;
    try {
      last = walk_expected_series(
          rates, *grid, start,
          [&](const BayindirState& state, std::int64_t step) {
            visit(to_model_row(state, rates.forms_aggregates, true, 0, step));
          },
          progress);
    } catch (const InputError& e) {
      throw InputError("model: the bayindir `" + variant + "` variant: " + e.what());
    }
    std::vector<TidyValue> extra;
    if (rates.forms_aggregates) {
      add_size_distribution(extra, grid->back(), last.aggregates);
      extra.push_back({std::string(kNoiseFloorQuantity) + kNoaMetric, std::nullopt,
                       noa_noise_floor(rates, *grid, start, replicates, seed,
                                       noise_floor_stream(variant), kNoiseFloorBatches, progress)});
    }
    extra.insert(extra.end(), notes.begin(), notes.end());
    return extra;
  };
  return pending;
}

// model.stochastic_replicates seeded replicates of `rates`, drawn from `stream`.
PendingVariant bayindir_stochastic(const WorldSpec& world, const BayindirRates& rates,
                                   const std::string& variant, std::uint64_t stream,
                                   const SharedGrid& grid, const std::vector<double>& start) {
  const int replicates = world.model.stochastic_replicates;
  const std::uint64_t seed = world.run.seed;
  const double work = static_cast<double>(grid->back()) * replicates;
  PendingVariant pending{
      .header = {.model = "bayindir", .variant = variant + "-stochastic", .stochastic = true},
      .walk_rows_work = work,
      .walk_steps_work = work};
  pending.walk_rows = [=](const RowVisitor& visit, const WalkProgress& progress) {
    walk_stochastic_replicates(
        rates, *grid, seed, replicates, stream, start,
        [&](const BayindirState& state, int replicate, std::int64_t step) {
          visit(to_model_row(state, rates.forms_aggregates, false, replicate, step));
        },
        progress);
    return std::vector<TidyValue>{};
  };
  pending.walk_steps = [=](const StepVisitor& visit, const WalkProgress& progress) {
    std::vector<ModelRow> rows(static_cast<std::size_t>(replicates));
    walk_stochastic_side_by_side(
        rates, *grid, seed, replicates, stream, start,
        [&](std::span<const BayindirState> states, std::int64_t step) {
          for (std::size_t k = 0; k < states.size(); ++k) {
            rows[k] =
                to_model_row(states[k], rates.forms_aggregates, false, static_cast<int>(k), step);
          }
          visit(rows);
        },
        progress);
  };
  return pending;
}

std::vector<PendingVariant> bayindir_predictions(const WorldSpec& world,
                                                 const MeasuredTerms* measured,
                                                 const std::vector<double>& start) {
  const SharedGrid grid = std::make_shared<const std::vector<std::int64_t>>(record_grid(world));
  std::vector<PendingVariant> predictions;
  for (const CreationVariant variant : kCreationVariants) {
    predictions.push_back(bayindir_expected(world, bayindir_rates(world, variant),
                                            creation_variant_name(variant), grid, start));
    predictions.back().header.chosen = variant == world.model.creation;
  }
  if (knows_returns(world)) {
    predictions.push_back(
        bayindir_expected(world, returns_bayindir_rates(world), kReturnsVariant, grid, start));
  }
  if (measured) {
    predictions.push_back(bayindir_expected(world, measured_bayindir_rates(world, *measured),
                                            "measured", grid, start,
                                            measured_term_notes(world, *measured)));
  }
  if (world.model.stochastic_replicates <= 0) return predictions;
  for (const CreationVariant variant : kCreationVariants) {
    predictions.push_back(bayindir_stochastic(world, bayindir_rates(world, variant),
                                              creation_variant_name(variant),
                                              static_cast<std::uint64_t>(variant), grid, start));
    predictions.back().header.chosen = variant == world.model.creation;
  }
  if (knows_returns(world)) {
    predictions.push_back(bayindir_stochastic(world, returns_bayindir_rates(world), kReturnsVariant,
                                              kReturnsStream, grid, start));
  }
  if (measured) {
    predictions.push_back(bayindir_stochastic(world, measured_bayindir_rates(world, *measured),
                                              "measured", kMeasuredStream, grid, start));
  }
  return predictions;
}

// A partition-model variant, computed whole when walked: its rows are a few report steps
// (models/soysal_model.hpp), whatever the run's length.
PendingVariant soysal_variant(const std::shared_ptr<const WorldSpec>& world,
                              const SoysalRates& rates, const std::string& variant,
                              const std::vector<double>& start,
                              const std::shared_ptr<const std::map<Partition, double>>& partitions,
                              const std::vector<TidyValue>& notes = {}) {
  PendingVariant pending{.header = {.model = "soysal", .variant = variant},
                         .walk_rows_work = static_cast<double>(world->steps())};
  pending.walk_rows = [=](const RowVisitor& visit, const WalkProgress& progress) {
    VariantPrediction prediction =
        soysal_prediction(*world, rates, variant, start, partitions.get());
    for (const ModelRow& row : prediction.series) visit(row);
    if (progress) progress(world->steps());
    prediction.extra.insert(prediction.extra.end(), notes.begin(), notes.end());
    return std::move(prediction.extra);
  };
  return pending;
}

std::string format(const char* pattern, double a, double b = 0.0) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, pattern, a, b);
  return buffer;
}

// The quantity a variant is judged by: NOA, or encounters for the collision check.
std::optional<double> headline(const ModelRow& row) {
  return row.noa ? row.noa : row.encounters;
}

std::string final_value_summary(const VariantPrediction& prediction) {
  const std::int64_t last_step = prediction.series.back().step;
  const char* name = prediction.series.back().noa ? "NOA" : "encounters";
  std::vector<double> finals;
  for (const ModelRow& row : prediction.series) {
    if (row.step == last_step && headline(row)) finals.push_back(*headline(row));
  }
  std::string text = std::string(name) + " at step " + std::to_string(last_step) + ": ";
  if (!prediction.stochastic) return text + format("%.4g", finals.front());
  return text + format("%.4g +- %.2g", sample_mean(finals), sample_sd(finals)) +
         " (mean +- sd of " + std::to_string(finals.size()) + " replicates)";
}

std::string stationary_summary(const VariantPrediction& prediction) {
  const TidyValue* most_likely = nullptr;
  const TidyValue* noa = nullptr;
  for (const TidyValue& value : prediction.extra) {
    if (value.quantity.starts_with("stationary:") &&
        (!most_likely || value.value > most_likely->value)) {
      most_likely = &value;
    }
    if (value.quantity == "stationary_noa") noa = &value;
  }
  if (!most_likely || !noa) return "";
  return "; stationary NOA " + format("%.4g", noa->value) + ", most likely partition " +
         most_likely->quantity.substr(std::string("stationary:").size()) +
         format(" (p = %.3g)", most_likely->value);
}

}  // namespace

std::vector<PendingVariant> pending_predictions(const WorldSpec& world,
                                                const MeasuredTerms* measured,
                                                const PlacementSample* sample) {
  const ModelFamily model = controller_rules(world).model;
  if (model == ModelFamily::None) return {};
  check_predictable(world);  // a refused world is refused for what it is, sample or none
  if (measured) check_measured_terms(world, *measured);
  const std::vector<double> start = start_aggregates(world, measured, sample);
  if (model != ModelFamily::Soysal) return bayindir_predictions(world, measured, start);
  const auto shared_world = std::make_shared<const WorldSpec>(world);
  std::shared_ptr<const std::map<Partition, double>> partitions;
  if (const std::map<Partition, double>* sampled = start_partitions(world, sample))
    partitions = std::make_shared<const std::map<Partition, double>>(*sampled);
  const auto soysal = [&](const SoysalRates& rates, const std::string& variant,
                          const std::vector<TidyValue>& notes = {}) {
    return soysal_variant(shared_world, rates, variant, start, partitions, notes);
  };
  std::vector<PendingVariant> predictions;
  for (const LeavingVariant variant : {LeavingVariant::Original, LeavingVariant::Peripheral}) {
    predictions.push_back(soysal(soysal_rates(world, variant), leaving_variant_name(variant)));
    predictions.back().header.chosen = variant == world.model.leaving;
  }
  if (knows_returns(world))
    predictions.push_back(soysal(returns_soysal_rates(world), kReturnsVariant));
  if (measured) {
    predictions.push_back(soysal(measured_soysal_rates(world, *measured), "measured",
                                 measured_term_notes(world, *measured)));
  }
  return predictions;
}

std::vector<VariantPrediction> predict(const WorldSpec& world, const MeasuredTerms* measured,
                                       const PlacementSample* sample) {
  std::vector<VariantPrediction> predictions;
  for (const PendingVariant& pending : pending_predictions(world, measured, sample))
    predictions.push_back(collect(pending));
  return predictions;
}

void check_predictable(const WorldSpec& world) {
  const ModelFamily model = controller_rules(world).model;
  if (model == ModelFamily::Soysal) check_partition_chain_size(world);
  if (model != ModelFamily::Bayindir && model != ModelFamily::Encounters) return;
  for (const CreationVariant variant : kCreationVariants) bayindir_rates(world, variant);
}

std::vector<std::string> model_caveats(const WorldSpec& world) {
  std::vector<std::string> caveats;
  const ControllerSpec& controller = world.controller;
  const ControllerRules rules = controller_rules(world);
  if (rules.model == ModelFamily::None) return caveats;
  if (rules.model == ModelFamily::Encounters) {
    caveats.push_back(
        "the encounter prediction assumes all N agents keep moving at speed v with uniform "
        "headings (collision_mode: ghost); in collision_mode: paper the leave runs after each "
        "encounter are not modelled");
    return caveats;
  }
  if (world.model.initial_state == InitialState::PlacementSecondOrder &&
      !world.robots.random_placement()) {
    caveats.push_back(
        "model.initial_state: placement_second_order expects a random placement; with given "
        "positions the models start from all searching (`placement` starts from their first "
        "decision)");
  }
  if (world.model.initial_state == InitialState::PlacementSecondOrder &&
      world.robots.random_placement()) {
    const double neighbours = (world.robots.count - 1) * placement_pair_probability(world);
    if (neighbours > kSecondOrderNeighbours) {
      caveats.push_back(
          "model.initial_state: placement_second_order: each agent starts with " +
          format("%.2g", neighbours) + " others within s on average; the formula holds below " +
          format("%.2g", kSecondOrderNeighbours) +
          " (it leaves out that a group must lie apart from the rest, and groups of four and "
          "more): `placement` samples the first decision instead");
    }
  }
  if (rules.leaves) {
    caveats.push_back(
        "the models have no LEAVE timeout: an agent that leaves is counted as free at once "
        "(the `returns` variant discounts the leavers that come back; docs/models-returns.md)");
  }
  if (rules.model == ModelFamily::Bayindir && controller.isolated_wait == IsolatedWait::Stay) {
    caveats.push_back(
        "the Bayindir model assumes isolated_wait: resume (a dissolved pair frees both agents)");
  }
  if (rules.model == ModelFamily::Soysal && controller.leave_size == LeaveSize::Neighbours) {
    caveats.push_back(
        "the partition model takes P_l(i) from the aggregate size i, not from the neighbour "
        "count (leave_size: neighbours)");
  }
  if (world.arena.topology == Topology::Walls) {
    caveats.push_back(
        "the models assume agents spread uniformly over the arena area; walls are not modelled");
  }
  return caveats;
}

std::string prediction_summary(const VariantPrediction& prediction) {
  std::string text = prediction.model + " " + prediction.variant + ": ";
  if (prediction.series.empty()) return text + "no prediction";
  return text + final_value_summary(prediction) + stationary_summary(prediction) +
         (prediction.chosen ? " [the world's model variant]" : "");
}

}  // namespace swarmagg
