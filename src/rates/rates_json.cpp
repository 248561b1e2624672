#include "rates/rates_json.hpp"

#include <nlohmann/json.hpp>

#include "config/world_writer.hpp"
#include "controllers/controller_registry.hpp"
#include "models/measured_rates.hpp"
#include "rates/geometry_fits.hpp"

namespace swarmagg {

namespace {

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json row_json(const RateRow& row) {
  const RateEstimate& e = row.estimate;
  nlohmann::json json = {
      {"term", row.term},
      {"size", row.size ? nlohmann::json(*row.size) : nlohmann::json(nullptr)},
      {"events", e.events},
      {"exposure", e.exposure},
      {"rate", optional_json(e.rate)},
      {"ci95", e.rate ? nlohmann::json::array({*e.low, *e.high}) : nlohmann::json(nullptr)},
      {"too_few_events", e.too_few()}};
  nlohmann::json models = nlohmann::json::object();
  for (const ModelTerm& m : row.models) {
    nlohmann::json model = {{"rate", m.rate}};
    if (e.rate && m.rate > 0.0) {
      model["ratio"] = *e.rate / m.rate;
      model["ratio_ci95"] = {*e.low / m.rate, *e.high / m.rate};
    }
    models[m.model + "/" + m.variant] = model;
  }
  json["models"] = models;
  return json;
}

}  // namespace

std::string rates_json(const WorldSpec& world, const RateTally& tally,
                       const std::vector<RateRow>& rows) {
  nlohmann::json terms = nlohmann::json::array();
  for (const RateRow& row : rows) terms.push_back(row_json(row));
  // The encounter check's agents all keep moving: every agent counts as searching.
  const bool collision = controller_rules(world).model == ModelFamily::Encounters;
  nlohmann::json json = {
      {"world", world.name},
      {"resolved_world", world_to_yaml(world)},
      {"replicates", tally.replicates},
      {"dt", world.engine.dt},
      {"exposure_steps", tally.steps},
      {"units",
       "rates per tu: creation/pairup per searcher pair, growth/join per (searcher, size-m "
       "aggregate) pair, attempt/escape per size-m aggregate; initial: aggregates per "
       "replicate after the first decision; radius (u) and rim (members): means over the "
       "size-m aggregates seen at the recorded steps, events = exposure = observations, 95% "
       "t interval with each replicate one cluster"},
      {"searchers", collision ? "every agent (a collision world's agents all keep moving)"
                              : "every agent in no aggregate, as the models count them "
                                "(LEAVE agents included: the models have no leave timeout)"},
      {"first_decision",
       "the first decision's pairs (placement put agents within s) are not encounters: its events "
       "and the exposure before it are left out of the rates and reported as the `initial` term"},
      {"minimum_events", kMinimumEvents},
      {"interval", "exact Poisson (Garwood) 95%, given the exposure"},
      {"terms", terms},
  };
  if (!collision) {
    json["geometry_fits"] = geometry_fits_json(fit_geometry_laws(rows, world.robots.radius));
  }
  if (!collision) json["measured_variant"] = measured_variant_note(world, measured_terms(rows));
  return json.dump(2) + "\n";
}

}  // namespace swarmagg
