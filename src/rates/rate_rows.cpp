#include "rates/rate_rows.hpp"

#include <algorithm>
#include <cmath>

#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "models/aggregate_shape.hpp"
#include "models/bayindir_rates.hpp"
#include "models/initial_state.hpp"
#include "models/kinetic_rate.hpp"
#include "models/return_probability.hpp"
#include "models/soysal_model.hpp"
#include "models/soysal_rates.hpp"
#include "rates/binomial_interval.hpp"

namespace swarmagg {

namespace {

constexpr CreationVariant kCreationVariants[] = {CreationVariant::Original,
                                                 CreationVariant::Collision};
constexpr LeavingVariant kLeavingVariants[] = {LeavingVariant::Original,
                                               LeavingVariant::Peripheral};

std::string creation_variant_name(CreationVariant variant) {
  return variant == CreationVariant::Original ? "original" : "collision";
}

// Which model the measured terms are set beside: the world's controller says (its rules).
ModelFamily model_of(const WorldSpec& world) {
  return controller_rules(world).model;
}

bool is_soysal(const WorldSpec& world) {
  return model_of(world) == ModelFamily::Soysal;
}

// Bayindir's NOA model and the encounter check share the creation terms.
bool is_bayindir(const WorldSpec& world) {
  const ModelFamily model = model_of(world);
  return model == ModelFamily::Bayindir || model == ModelFamily::Encounters;
}

// Per-step model probabilities, or none when the model refuses the world (dt too coarse):
// the measurement stands on its own then.
std::vector<std::pair<std::string, BayindirRates>> bayindir_variants(const WorldSpec& world) {
  std::vector<std::pair<std::string, BayindirRates>> variants;
  try {
    for (const CreationVariant v : kCreationVariants)
      variants.emplace_back(creation_variant_name(v), bayindir_rates(world, v));
  } catch (const InputError&) {
    variants.clear();
  }
  return variants;
}

std::vector<std::pair<std::string, SoysalRates>> soysal_variants(const WorldSpec& world) {
  std::vector<std::pair<std::string, SoysalRates>> variants;
  for (const LeavingVariant v : kLeavingVariants)
    variants.emplace_back(leaving_variant_name(v), soysal_rates(world, v));
  return variants;
}

// Every variant's name, for terms all variants share.
std::vector<std::string> variant_names(const WorldSpec& world) {
  std::vector<std::string> names;
  if (is_soysal(world)) {
    for (const LeavingVariant v : kLeavingVariants) names.push_back(leaving_variant_name(v));
  } else if (is_bayindir(world)) {
    for (const CreationVariant v : kCreationVariants) names.push_back(creation_variant_name(v));
  }
  return names;
}

RateRow creation_row(const WorldSpec& world, const RateTally& tally) {
  const double dt = world.engine.dt;
  RateRow row{
      .term = is_soysal(world) ? "pairup" : "creation",
      .estimate = estimate_rate(tally.creations, static_cast<double>(tally.pair_steps) * dt)};
  if (is_soysal(world)) {
    for (const auto& [name, rates] : soysal_variants(world))
      row.models.push_back({"soysal", name, rates.pair_up / dt});
  } else if (is_bayindir(world)) {
    for (const CreationVariant v : kCreationVariants) {
      // Expected creations per step coefficient * y (y - 1) (or y^2): per pair per tu, 2 c / dt.
      row.models.push_back({"bayindir", creation_variant_name(v),
                            2.0 * creation_per_step(world, v).coefficient / dt});
    }
  }
  return row;
}

// Joins per searcher per size-m aggregate per tu: every join (term growth, Soysal's join),
// or with `new_only` the joins that are not returns (join_new), whose exposure leaves out the
// agents away on an excursion that returned: they were no searchers. The models' join term
// is meant as the new-encounter rate.
void add_growth_rows(const WorldSpec& world, const RateTally& tally, bool new_only,
                     std::vector<RateRow>& rows) {
  const double dt = world.engine.dt;
  const auto bayindir =
      is_bayindir(world) ? bayindir_variants(world) : decltype(bayindir_variants(world)){};
  const auto soysal =
      is_soysal(world) ? soysal_variants(world) : decltype(soysal_variants(world)){};
  for (int m = 2; m < tally.agents; ++m) {
    const auto index = static_cast<std::size_t>(m);
    if (tally.searcher_aggregate_steps[index] == 0 && tally.growths[index] == 0) continue;
    const std::uint64_t returned =
        new_only ? std::min(tally.returns_into[index], tally.growths[index]) : 0;
    const std::uint64_t away = new_only ? std::min(tally.returning_searcher_steps[index],
                                                   tally.searcher_aggregate_steps[index])
                                        : 0;
    RateRow row{.term = new_only           ? "join_new"
                        : is_soysal(world) ? "join"
                                           : "growth",
                .size = m,
                .estimate = estimate_rate(
                    tally.growths[index] - returned,
                    static_cast<double>(tally.searcher_aggregate_steps[index] - away) * dt)};
    for (const auto& [name, rates] : bayindir)
      row.models.push_back({"bayindir", name, rates.growth[index] / dt});
    for (const auto& [name, rates] : soysal)
      row.models.push_back({"soysal", name, rates.join[index] / dt});
    rows.push_back(row);
  }
}

// Per size m left: the fraction of LEAVE attempts that returned (binomial interval), against
// the `returns` variant's q over every attempt (models/return_probability.hpp), and their
// mean time away in tu.
void add_return_rows(const WorldSpec& world, const RateTally& tally, std::vector<RateRow>& rows) {
  const double dt = world.engine.dt;
  const std::string model = is_soysal(world) ? "soysal" : "bayindir";
  for (int m = 2; m <= tally.agents; ++m) {
    const auto index = static_cast<std::size_t>(m);
    if (tally.return_attempts[index] == 0) continue;
    RateRow row{.term = "return",
                .size = m,
                .estimate = estimate_fraction(tally.returns[index], tally.return_attempts[index])};
    row.models.push_back({model, kReturnsVariant, attempt_return_probability(world, m)});
    rows.push_back(row);
  }
  for (int m = 2; m <= tally.agents; ++m) {
    const auto index = static_cast<std::size_t>(m);
    if (tally.returns[index] == 0) continue;
    const auto returns = static_cast<double>(tally.returns[index]);
    RateRow row{.term = "return_time",
                .size = m,
                .estimate = {.events = tally.returns[index], .exposure = returns}};
    if (tally.returns[index] >= kMinimumEvents) {
      // The mean and its normal 95% interval (the times of returns are independent enough:
      // each is one agent's excursion).
      const double mean = static_cast<double>(tally.return_steps[index]) / returns;
      const double variance = std::max(
          0.0, (static_cast<double>(tally.return_square_steps[index]) / returns - mean * mean) *
                   returns / (returns - 1.0));
      const double half = 1.96 * std::sqrt(variance / returns);
      row.estimate.rate = mean * dt;
      row.estimate.low = (mean - half) * dt;
      row.estimate.high = (mean + half) * dt;
    }
    rows.push_back(row);
  }
}

// The models' start by size: the sample, or the second-order formula's pairs and triples.
std::vector<double> initial_predictions(const WorldSpec& world, int agents,
                                        const PlacementSample* sample) {
  if (sample) return sample->aggregates;
  std::vector<double> predicted(static_cast<std::size_t>(agents) + 1, 0.0);
  const FirstDecision first = expected_first_decision(world);
  if (agents >= 2) predicted[2] = first.pairs;
  if (agents >= 3) predicted[3] = first.triples;
  return predicted;
}

void add_initial_rows(const WorldSpec& world, const RateTally& tally, const PlacementSample* sample,
                      std::vector<RateRow>& rows) {
  const bool expected = sample || world.robots.random_placement();
  const std::vector<double> start =
      expected ? initial_predictions(world, tally.agents, sample) : std::vector<double>{};
  const std::string model = is_soysal(world) ? "soysal" : "bayindir";
  for (int m = 2; m <= tally.agents; ++m) {
    const auto index = static_cast<std::size_t>(m);
    const double predicted = index < start.size() ? start[index] : 0.0;
    if (tally.initial_aggregates[index] == 0 && m > 2 && predicted == 0.0) continue;
    RateRow row{.term = "initial",
                .size = m,
                .estimate = estimate_rate(tally.initial_aggregates[index],
                                          static_cast<double>(tally.replicates))};
    if (expected) {
      for (const std::string& name : variant_names(world))
        row.models.push_back({model, name, predicted});
    }
    rows.push_back(row);
  }
}

// Leave attempts and escapes per aggregate of size m per tu. Models: attempts m P_l(m) / dt
// (every member may try: m p for Bayindir); escapes are what each variant loses, Bayindir's
// p min(m, periph(m)) (2p for pairs), Soysal's L(m) of the variant.
void add_leave_rows(const WorldSpec& world, const RateTally& tally, std::vector<RateRow>& rows) {
  const double dt = world.engine.dt;
  const auto bayindir =
      is_bayindir(world) ? bayindir_variants(world) : decltype(bayindir_variants(world)){};
  const auto soysal =
      is_soysal(world) ? soysal_variants(world) : decltype(soysal_variants(world)){};
  const std::string model = is_soysal(world) ? "soysal" : "bayindir";
  const auto at_size = registration_of(world.controller.type).leave_probability_at_size;
  for (const std::string term : {"attempt", "escape"}) {
    const std::vector<std::uint64_t>& events = term == "attempt" ? tally.attempts : tally.escapes;
    for (int m = 2; m <= tally.agents; ++m) {
      const auto index = static_cast<std::size_t>(m);
      if (tally.leave_aggregate_steps[index] == 0 && events[index] == 0) continue;
      RateRow row{.term = term,
                  .size = m,
                  .estimate = estimate_rate(
                      events[index], static_cast<double>(tally.leave_aggregate_steps[index]) * dt)};
      if (term == "attempt" && at_size) {
        for (const std::string& name : variant_names(world))
          row.models.push_back({model, name, m * at_size(world, m) / dt});
      } else if (term == "escape") {
        for (const auto& [name, rates] : bayindir)
          row.models.push_back({"bayindir", name, rates.loss[index] / dt});
        for (const auto& [name, rates] : soysal)
          row.models.push_back({"soysal", name, rates.leave[index] / dt});
      }
      rows.push_back(row);
    }
  }
}

// The mean outer radius R1 and rim count of size-m aggregates, against the laws each variant
// builds on: R1 = r' 1.20 m^0.48 (r' = s/4 for Bayindir, r for Soysal) and the periphery
// pi (1.20 m^0.48 - 1) (Bayindir caps it at m in both variants; only Soysal's peripheral
// variant has one, capped as model.periphery_cap says).
void add_geometry_rows(const WorldSpec& world, const RateTally& tally, std::vector<RateRow>& rows) {
  const std::string model = is_soysal(world) ? "soysal" : "bayindir";
  const double model_radius = is_soysal(world) ? world.robots.radius : bayindir_agent_radius(world);
  for (const std::string term : {"radius", "rim"}) {
    const std::vector<ClusteredMean>& means = term == "radius" ? tally.outer_radius : tally.rim;
    for (int m = 2; m <= tally.agents; ++m) {
      const ClusteredMean& mean = means[static_cast<std::size_t>(m)];
      if (mean.observations() == 0) continue;
      RateRow row{.term = term, .size = m, .estimate = mean.estimate()};
      if (term == "radius") {
        for (const std::string& name : variant_names(world))
          row.models.push_back({model, name, aggregate_radius(model_radius, m)});
      } else if (is_soysal(world)) {
        row.models.push_back({model, leaving_variant_name(LeavingVariant::Peripheral),
                              soysal_leavers(world, LeavingVariant::Peripheral, m)});
      } else {
        for (const std::string& name : variant_names(world))
          row.models.push_back({model, name, capped_periphery_agents(m)});
      }
      rows.push_back(row);
    }
  }
}

}  // namespace

std::vector<RateRow> measured_rate_rows(const WorldSpec& world, const RateTally& tally,
                                        const PlacementSample* placement_start) {
  std::vector<RateRow> rows{creation_row(world, tally)};
  const ControllerRules rules = controller_rules(world);
  if (rules.model == ModelFamily::Encounters) return rows;
  if (rules.joins) add_growth_rows(world, tally, false, rows);
  if (rules.joins && rules.leaves) add_growth_rows(world, tally, true, rows);
  if (rules.leaves) {
    add_leave_rows(world, tally, rows);
    add_return_rows(world, tally, rows);
  }
  add_initial_rows(world, tally, placement_start, rows);
  add_geometry_rows(world, tally, rows);
  return rows;
}

MeasuredTerms measured_terms(const std::vector<RateRow>& rows) {
  MeasuredTerms terms;
  for (const RateRow& row : rows) {
    if ((row.term == "creation" || row.term == "pairup") && row.estimate.rate) {
      terms.creation = row.estimate.rate;
    } else if ((row.term == "growth" || row.term == "join") && row.size && row.estimate.rate) {
      terms.growth[*row.size] = *row.estimate.rate;
    } else if (row.term == "return" && row.size && row.estimate.rate) {
      terms.returned[*row.size] = *row.estimate.rate;
    } else if (row.term == "join_new" && row.size && row.estimate.rate) {
      terms.new_growth[*row.size] = *row.estimate.rate;
    } else if (row.term == "attempt" && row.size && row.estimate.rate) {
      terms.attempt[*row.size] = *row.estimate.rate;
    } else if (row.term == "initial" && row.size && row.estimate.exposure > 0.0) {
      terms.initial[*row.size] = static_cast<double>(row.estimate.events) / row.estimate.exposure;
    }
  }
  return terms;
}

}  // namespace swarmagg
