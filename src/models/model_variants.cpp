#include "models/model_variants.hpp"

#include <memory>
#include <span>

#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "models/bayindir_expected.hpp"
#include "models/bayindir_stochastic.hpp"
#include "models/measured_rates.hpp"
#include "models/model_series.hpp"
#include "models/noise_floor.hpp"
#include "models/output_grid.hpp"
#include "models/return_probability.hpp"
#include "models/returns_rates.hpp"
#include "models/soysal_model.hpp"
#include "models/soysal_rates.hpp"

namespace swarmagg {

namespace {

std::string creation_variant_name(CreationVariant variant) {
  return variant == CreationVariant::Original ? "original" : "collision";
}

// Streams of the measured and returns variants' stochastic draws (the creation variants
// use 0 and 1).
constexpr std::uint64_t kMeasuredStream = 2;
constexpr std::uint64_t kReturnsStream = 3;

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
  pending.walk_rows = [=](const RowVisitor& visit, const WalkProgress& progress, Extras extras) {
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
    if (extras == Extras::Skipped) return extra;
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
  // A stochastic variant has no extra values.
  pending.walk_rows = [=](const RowVisitor& visit, const WalkProgress& progress, Extras) {
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

// A partition-model variant, computed whole when walked: its rows are a few report steps
// (models/soysal_model.hpp), whatever the run's length.
PendingVariant soysal_variant(const std::shared_ptr<const WorldSpec>& world,
                              const SoysalRates& rates, const std::string& variant,
                              const std::vector<double>& start,
                              const std::shared_ptr<const std::map<Partition, double>>& partitions,
                              const std::vector<TidyValue>& notes = {}) {
  PendingVariant pending{.header = {.model = "soysal", .variant = variant},
                         .walk_rows_work = static_cast<double>(world->steps())};
  pending.walk_rows = [=](const RowVisitor& visit, const WalkProgress& progress, Extras extras) {
    VariantPrediction prediction =
        soysal_prediction(*world, rates, variant, start, partitions.get(), progress);
    for (const ModelRow& row : prediction.series) visit(row);
    if (progress) progress(world->steps());
    if (extras == Extras::Skipped) return std::vector<TidyValue>{};
    prediction.extra.insert(prediction.extra.end(), notes.begin(), notes.end());
    return std::move(prediction.extra);
  };
  return pending;
}

}  // namespace

bool knows_returns(const WorldSpec& world) {
  const ControllerRules rules = controller_rules(world);
  return rules.leaves && rules.model != ModelFamily::Encounters;
}

std::vector<PendingVariant> bayindir_variants(const WorldSpec& world, const MeasuredTerms* measured,
                                              const std::vector<double>& start) {
  // Each set of rates once: its expected-value variant, and its stochastic one after all of
  // those (model.csv's order), drawn from its own stream.
  struct Rated {
    BayindirRates rates;
    std::string name;
    std::uint64_t stream;
    bool chosen = false;
    std::vector<TidyValue> notes = {};
  };
  std::vector<Rated> rated;
  for (const CreationVariant variant : kCreationVariants) {
    rated.push_back({bayindir_rates(world, variant), creation_variant_name(variant),
                     static_cast<std::uint64_t>(variant), variant == world.model.creation});
  }
  if (knows_returns(world))
    rated.push_back({returns_bayindir_rates(world), kReturnsVariant, kReturnsStream});
  if (measured) {
    rated.push_back({measured_bayindir_rates(world, *measured), "measured", kMeasuredStream, false,
                     measured_term_notes(world, *measured)});
  }
  const SharedGrid grid = std::make_shared<const std::vector<std::int64_t>>(record_grid(world));
  std::vector<PendingVariant> predictions;
  for (const Rated& r : rated) {
    predictions.push_back(bayindir_expected(world, r.rates, r.name, grid, start, r.notes));
    predictions.back().header.chosen = r.chosen;
  }
  if (world.model.stochastic_replicates <= 0) return predictions;
  for (const Rated& r : rated) {
    predictions.push_back(bayindir_stochastic(world, r.rates, r.name, r.stream, grid, start));
    predictions.back().header.chosen = r.chosen;
  }
  return predictions;
}

std::vector<PendingVariant> soysal_variants(const WorldSpec& world, const MeasuredTerms* measured,
                                            const std::vector<double>& start,
                                            const std::map<Partition, double>* start_partitions) {
  const auto shared_world = std::make_shared<const WorldSpec>(world);
  std::shared_ptr<const std::map<Partition, double>> partitions;
  if (start_partitions)
    partitions = std::make_shared<const std::map<Partition, double>>(*start_partitions);
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

}  // namespace swarmagg
