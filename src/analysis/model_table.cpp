#include "analysis/model_table.hpp"

#include <cmath>

namespace swarmagg {
namespace {

ModelCurve& curve_of(std::vector<ModelCurve>& curves, const std::string& variant) {
  for (ModelCurve& curve : curves) {
    if (curve.variant == variant) return curve;
  }
  return curves.emplace_back(ModelCurve{variant, {}, {}});
}

}  // namespace

std::vector<ModelCurve> model_curves(const CsvTable& model, const std::string& quantity) {
  const std::size_t variant = model.column("variant"), time = model.column("time"),
                    name = model.column("quantity"), value = model.column("value");
  std::vector<ModelCurve> curves;
  for (std::size_t row = 0; row < model.rows.size(); ++row) {
    if (model.rows[row][name] != quantity || std::isnan(model.number(row, time))) continue;
    ModelCurve& curve = curve_of(curves, model.rows[row][variant]);
    curve.x.push_back(model.number(row, time));
    curve.y.push_back(model.number(row, value));
  }
  return curves;
}

std::vector<ModelCurve> model_curves_by_suffix(const CsvTable& model, const std::string& prefix) {
  const std::size_t variant = model.column("variant"), name = model.column("quantity"),
                    value = model.column("value");
  std::vector<ModelCurve> curves;
  for (std::size_t row = 0; row < model.rows.size(); ++row) {
    const std::string& quantity = model.rows[row][name];
    if (!quantity.starts_with(prefix)) continue;
    ModelCurve& curve = curve_of(curves, model.rows[row][variant]);
    curve.x.push_back(std::stod(quantity.substr(prefix.size())));
    curve.y.push_back(model.number(row, value));
  }
  return curves;
}

}  // namespace swarmagg
