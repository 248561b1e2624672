#include "plot/model_curve_lines.hpp"

#include <algorithm>
#include <map>

#include "analysis/csv_text.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/variant_colours.hpp"

namespace swarmagg {
namespace {

constexpr std::string_view kStochastic = "-stochastic";

std::string base_variant(const std::string& variant) {
  return variant.ends_with(kStochastic) ? variant.substr(0, variant.size() - kStochastic.size())
                                        : variant;
}

}  // namespace

std::string model_curve_lines(const std::vector<ModelCurve>& curves, const FigureFiles& files,
                              const std::string& part, const std::string& style, double missing) {
  if (curves.empty()) return "";
  std::map<double, std::vector<double>> rows;
  for (std::size_t v = 0; v < curves.size(); ++v) {
    for (std::size_t i = 0; i < curves[v].x.size(); ++i) {
      auto [row, inserted] = rows.try_emplace(curves[v].x[i], curves.size(), missing);
      row->second[v] = curves[v].y[i];
    }
  }
  std::string csv = "x";
  for (const ModelCurve& curve : curves) csv += "," + curve.variant;
  csv += "\n";
  for (const auto& [x, values] : rows) {
    csv += csv_number(x);
    for (const double value : values) csv += "," + csv_number(value);
    csv += "\n";
  }
  write_file_atomic(files.csv(part), csv);

  std::vector<std::string> bases;
  std::string lines;
  const std::string data = gnuplot_quote(files.csv_name(part));
  for (std::size_t v = 0; v < curves.size(); ++v) {
    const std::string base = base_variant(curves[v].variant);
    if (std::find(bases.begin(), bases.end(), base) == bases.end()) bases.push_back(base);
    const auto colour =
        static_cast<std::size_t>(std::find(bases.begin(), bases.end(), base) - bases.begin());
    const bool stochastic = base != curves[v].variant;
    lines += ", \\\n  " + data + " skip 1 using 1:" + std::to_string(v + 2) + " with " + style +
             (stochastic ? " dt 2" : "") + " lc rgb " + gnuplot_quote(variant_colour(colour)) +
             " title " +
             gnuplot_quote("model " + curves[v].variant + (stochastic ? " (mean)" : ""));
  }
  return lines;
}

}  // namespace swarmagg
