#include "models/measured_rates.hpp"

#include "controllers/controller_registry.hpp"

namespace swarmagg {

namespace {

int growth_sizes_used(const WorldSpec& world, const MeasuredTerms& terms) {
  if (!world.controller.join) return 0;
  int used = 0;
  for (const auto& [size, rate] : terms.growth) used += size >= 2 && size < world.robots.count;
  return used;
}

int leave_sizes_used(const WorldSpec& world, const MeasuredTerms& terms) {
  if (!world.controller.leave) return 0;
  int used = 0;
  for (const auto& [size, rate] : terms.attempt) used += size >= 2 && size <= world.robots.count;
  return used;
}

}  // namespace

BayindirRates measured_bayindir_rates(const WorldSpec& world, const MeasuredTerms& terms) {
  BayindirRates rates = bayindir_rates(world, world.model.creation);
  const double dt = world.engine.dt;
  // Expected creations per step among y searchers: rate per pair * dt * y (y - 1) / 2.
  if (terms.creation) rates.creation = {*terms.creation * dt / 2.0, PairCount::Ordered};
  if (!rates.forms_aggregates) return rates;
  if (world.controller.leave) {
    for (const auto& [size, rate] : terms.attempt) {
      if (size >= 2 && size <= rates.agents) rates.loss[static_cast<std::size_t>(size)] = rate * dt;
    }
  }
  if (!world.controller.join) return rates;
  for (const auto& [size, rate] : terms.growth) {
    if (size >= 2 && size < rates.agents) rates.growth[static_cast<std::size_t>(size)] = rate * dt;
  }
  return rates;
}

SoysalRates measured_soysal_rates(const WorldSpec& world, const MeasuredTerms& terms) {
  SoysalRates rates = soysal_rates(world, world.model.leaving);
  const double dt = world.engine.dt;
  if (terms.creation) rates.pair_up = *terms.creation * dt;
  if (world.controller.leave) {
    for (const auto& [size, rate] : terms.attempt) {
      if (size >= 2 && size <= rates.agents)
        rates.leave[static_cast<std::size_t>(size)] = rate * dt;
    }
  }
  if (!world.controller.join) return rates;
  for (const auto& [size, rate] : terms.growth) {
    if (size >= 2 && size < rates.agents) rates.join[static_cast<std::size_t>(size)] = rate * dt;
  }
  return rates;
}

std::vector<TidyValue> measured_term_notes(const WorldSpec& world, const MeasuredTerms& terms) {
  std::vector<TidyValue> notes = {
      {"terms:creation_measured", std::nullopt, terms.creation ? 1.0 : 0.0},
      {"terms:growth_sizes_measured", std::nullopt,
       static_cast<double>(growth_sizes_used(world, terms))}};
  if (world.controller.leave) {
    notes.push_back({"terms:leave_sizes_measured", std::nullopt,
                     static_cast<double>(leave_sizes_used(world, terms))});
  }
  return notes;
}

std::string measured_variant_note(const WorldSpec& world, const MeasuredTerms& terms) {
  std::string note = "measured variant: creation ";
  note += terms.creation ? "measured" : "from the model (too few events)";
  if (world.controller.join) {
    note += ", growth measured at " + std::to_string(growth_sizes_used(world, terms)) +
            " aggregate sizes (the model's capture radius elsewhere)";
  }
  const ControllerRules rules = controller_rules(world);
  if (rules.leaves && rules.model != ModelFamily::Encounters) {
    note += ", leaving at the measured LEAVE attempt rate at " +
            std::to_string(leave_sizes_used(world, terms)) +
            " aggregate sizes (attempts that do not escape come back as growths; the model's "
            "leave law elsewhere)";
  }
  return note;
}

}  // namespace swarmagg
