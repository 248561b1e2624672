#include "analysis/model_table.hpp"

#include <cmath>
#include <optional>

#include "analysis/csv_reader.hpp"
#include "core/errors.hpp"

namespace swarmagg {
namespace {

ModelCurve& curve_of(std::vector<ModelCurve>& curves, const std::string& variant) {
  for (ModelCurve& curve : curves) {
    if (curve.variant == variant) return curve;
  }
  return curves.emplace_back(ModelCurve{variant, {}, {}});
}

}  // namespace

std::vector<ModelCurve> model_curves(const std::filesystem::path& model_csv,
                                     const std::string& quantity, const StepFilter& keep) {
  CsvReader model(model_csv);
  const std::size_t variant = model.column("variant"), step = model.column("step"),
                    time = model.column("time"), name = model.column("quantity"),
                    value = model.column("value");
  std::vector<ModelCurve> curves;
  while (model.next()) {
    if (model.cell(name) != quantity || std::isnan(model.number(time))) continue;
    if (keep && !keep(std::llround(model.number(step)))) continue;
    ModelCurve& curve = curve_of(curves, model.cell(variant));
    curve.x.push_back(model.number(time));
    curve.y.push_back(model.number(value));
  }
  return curves;
}

std::vector<ModelCurve> model_curves_by_suffix(const std::filesystem::path& model_csv,
                                               const std::string& prefix, int largest) {
  CsvReader model(model_csv);
  const std::size_t variant = model.column("variant"), name = model.column("quantity"),
                    value = model.column("value");
  std::vector<ModelCurve> curves;
  while (model.next()) {
    const std::string& quantity = model.cell(name);
    if (!quantity.starts_with(prefix)) continue;
    const std::optional<double> size = parse_csv_number(quantity.substr(prefix.size()));
    if (!size || !std::isfinite(*size))
      throw_not_a_number(model_csv.string() + ":" + std::to_string(model.line()), "quantity",
                         quantity);
    // A size no run of the world can have (edited, damaged) would also size what draws it.
    if (*size != std::floor(*size) || *size < 2 || *size > largest) {
      throw InputError(model_csv.string() + ":" + std::to_string(model.line()) +
                       ": quantity: expected " + prefix + "<m> with m a whole number from 2 to " +
                       std::to_string(largest) + ", got '" + quantity +
                       "': the file was edited or damaged since; run the world again");
    }
    ModelCurve& curve = curve_of(curves, model.cell(variant));
    curve.x.push_back(*size);
    curve.y.push_back(model.number(value));
  }
  return curves;
}

}  // namespace swarmagg
