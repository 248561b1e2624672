#include "models/predictions.hpp"

#include <cstdio>

#include "controllers/controller_registry.hpp"
#include "models/initial_state.hpp"
#include "models/measured_rates.hpp"
#include "models/model_variants.hpp"
#include "models/sample_statistics.hpp"
#include "models/soysal_model.hpp"

namespace swarmagg {

namespace {

// Mean neighbours within s per agent above which placement_second_order is off by more than
// a tenth in the triples (docs/models.md, "Where the models start").
constexpr double kSecondOrderNeighbours = 0.1;

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
  if (model != ModelFamily::Soysal) return bayindir_variants(world, measured, start);
  return soysal_variants(world, measured, start, start_partitions(world, sample));
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

namespace {

// `general`: also the caveats every world of its model family shares.
std::vector<std::string> caveats_of(const WorldSpec& world, bool general) {
  std::vector<std::string> caveats;
  const ControllerSpec& controller = world.controller;
  const ControllerRules rules = controller_rules(world);
  if (rules.model == ModelFamily::None) return caveats;
  if (rules.model == ModelFamily::Encounters) {
    if (!general) return caveats;
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
  if (rules.leaves && general) {
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

}  // namespace

std::string no_model_note(const WorldSpec& world) {
  if (controller_rules(world).model != ModelFamily::None) return {};
  return "no macroscopic model describes controller type '" + world.controller.type +
         "' (docs/models.md): model.csv holds its header only";
}

std::vector<std::string> model_caveats(const WorldSpec& world) {
  return caveats_of(world, true);
}

std::vector<std::string> world_caveats(const WorldSpec& world) {
  return caveats_of(world, false);
}

std::string prediction_summary(const VariantPrediction& prediction) {
  std::string text = prediction.model + " " + prediction.variant + ": ";
  if (prediction.series.empty()) return text + "no prediction";
  return text + final_value_summary(prediction) + stationary_summary(prediction) +
         (prediction.chosen ? " [the world's model variant]" : "");
}

}  // namespace swarmagg
