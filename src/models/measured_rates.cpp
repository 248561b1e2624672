#include "models/measured_rates.hpp"

#include <cstdio>
#include <map>

#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"

namespace swarmagg {

namespace {

// The measured joins the variant grows by: the new joins (join_new) once returns are taken out
// of the losses anywhere, else every join. Never every join beside returns taken out: a
// return would then be no loss but still a join into any aggregate. A size without a measured
// rate keeps the model's term, the new encounters at its capture radius.
const std::map<int, double>& joins_used(const MeasuredTerms& terms) {
  return terms.returned.empty() ? terms.growth : terms.new_growth;
}

int growth_sizes_used(const WorldSpec& world, const MeasuredTerms& terms) {
  if (!world.controller.join) return 0;
  int used = 0;
  for (const auto& [size, rate] : joins_used(terms)) used += size >= 2 && size < world.robots.count;
  return used;
}

int leave_sizes_used(const WorldSpec& world, const MeasuredTerms& terms) {
  if (!world.controller.leave) return 0;
  int used = 0;
  for (const auto& [size, rate] : terms.attempt) used += size >= 2 && size <= world.robots.count;
  return used;
}

// Per size: the measured loss per step, attempt (1 - returned) (docs/models-returns.md).
double measured_loss(const MeasuredTerms& terms, int size, double attempt_rate, double dt) {
  const auto returned = terms.returned.find(size);
  return attempt_rate * dt * (1.0 - (returned == terms.returned.end() ? 0.0 : returned->second));
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
      if (size >= 2 && size <= rates.agents)
        rates.loss[static_cast<std::size_t>(size)] = measured_loss(terms, size, rate, dt);
    }
  }
  if (!world.controller.join) return rates;
  for (const auto& [size, rate] : joins_used(terms)) {
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
        rates.leave[static_cast<std::size_t>(size)] = measured_loss(terms, size, rate, dt);
    }
  }
  if (!world.controller.join) return rates;
  for (const auto& [size, rate] : joins_used(terms)) {
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
            " aggregate sizes (" + (terms.returned.empty() ? "" : "new joins, returns left out; ") +
            "the model's capture radius elsewhere)";
  }
  const ControllerRules rules = controller_rules(world);
  if (rules.leaves && rules.model != ModelFamily::Encounters) {
    note +=
        ", leaving at the measured LEAVE attempt rate times the fraction that does not "
        "return at " +
        std::to_string(leave_sizes_used(world, terms)) +
        " aggregate sizes (return fraction "
        "measured at " +
        std::to_string(terms.returned.size()) + "; the model's leave law elsewhere)";
  }
  return note;
}

namespace {

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

// The measured first decision must fit the world's agents: a start of other sizes (or of more
// agents) comes from another world or a damaged file.
void check_measured_start(const WorldSpec& world, const MeasuredTerms& terms) {
  const int agents = world.robots.count;
  double placed = 0.0;
  for (const auto& [size, count] : terms.initial) {
    if (size > agents) {
      throw InputError("measured initial state: aggregates of " + std::to_string(size) +
                       " agents in a world of " + std::to_string(agents));
    }
    placed += size * count;
  }
  if (placed > agents * (1.0 + 1e-9)) {
    throw InputError("measured initial state: its aggregates hold " + number(placed) +
                     " agents on average, more than the world's " + std::to_string(agents));
  }
}

}  // namespace

void check_measured_terms(const WorldSpec& world, const MeasuredTerms& terms) {
  const double dt = world.engine.dt;
  const auto refuse = [&](const std::string& term, double rate, const std::string& limit) {
    throw InputError("measured " + term + " rate " + number(rate) + " per tu is " + limit +
                     " in a step of dt = " + number(dt) +
                     ": not a rate a run of this world can measure");
  };
  // Named as the rates.csv of the world's model names them.
  const bool soysal = controller_rules(world).model == ModelFamily::Soysal;
  if (terms.creation && *terms.creation * dt > 1.0)
    refuse(soysal ? "pairup" : "creation", *terms.creation,
           "more than one pair-up per searcher pair");
  for (const auto* growth : {&terms.growth, &terms.new_growth}) {
    const std::string name = growth == &terms.new_growth ? "join_new" : soysal ? "join" : "growth";
    for (const auto& [size, rate] : *growth) {
      if (rate * dt > 1.0)
        refuse(name + " " + std::to_string(size), rate, "more than one join per searcher");
    }
  }
  for (const auto& [size, rate] : terms.attempt) {
    if (rate * dt > size)
      refuse("attempt " + std::to_string(size), rate, "more LEAVE attempts than members");
  }
  if (world.model.initial_state == InitialState::Measured) check_measured_start(world, terms);
}

}  // namespace swarmagg
