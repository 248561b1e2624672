#include "rates/geometry_fits.hpp"

#include <numbers>

#include "models/aggregate_shape.hpp"

namespace swarmagg {

namespace {

PowerLawFit fit_term(const std::vector<RateRow>& rows, const std::string& term,
                     double (*to_power_law)(double mean, double agent_radius),
                     double agent_radius) {
  std::vector<PowerLawPoint> points;
  for (const RateRow& row : rows) {
    if (row.term != term || !row.size || !row.estimate.rate) continue;
    points.push_back({static_cast<double>(*row.size),
                      to_power_law(*row.estimate.rate, agent_radius),
                      static_cast<double>(row.estimate.events)});
  }
  return fit_power_law(points);
}

nlohmann::json fit_json(const PowerLawFit& fit, const std::string& law) {
  nlohmann::json json = {{"law", law}, {"sizes", fit.sizes}};
  if (!fit.fitted()) {
    json["refused"] = fit.refused;
    return json;
  }
  json["a"] = fit.a->value;
  json["a_ci95"] = {fit.a->low, fit.a->high};
  json["b"] = fit.b->value;
  json["b_ci95"] = {fit.b->low, fit.b->high};
  json["paper_a_in_ci"] = fit.a->covers(kPaperPackingScale);
  json["paper_b_in_ci"] = fit.b->covers(kPaperPackingExponent);
  return json;
}

}  // namespace

GeometryFits fit_geometry_laws(const std::vector<RateRow>& rows, double agent_radius) {
  return {fit_term(
              rows, "radius", [](double mean, double r) { return mean / r; }, agent_radius),
          fit_term(
              rows, "rim", [](double mean, double) { return mean / std::numbers::pi + 1.0; },
              agent_radius)};
}

nlohmann::json geometry_fits_json(const GeometryFits& fits) {
  return {{"radius", fit_json(fits.radius, "R1 = r a m^b")},
          {"rim", fit_json(fits.rim, "rim = pi (a m^b - 1)")},
          {"paper", {{"a", kPaperPackingScale}, {"b", kPaperPackingExponent}}},
          {"weights", "observations per size; sizes with too few observations left out"}};
}

}  // namespace swarmagg
