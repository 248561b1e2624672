#include "reproduce/noa_plot.hpp"

#include <algorithm>

#include "analysis/csv_text.hpp"
#include "models/return_probability.hpp"
#include "models/sample_statistics.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/variant_colours.hpp"
#include "reproduce/paper_predictions.hpp"

namespace swarmagg {
namespace {

// Box statistics at kNoaBoxes evenly spaced recorded steps after the start.
std::string boxes_csv(const NoaSeries& simulation) {
  std::string text = "time,min,q25,median,q75,max,mean\n";
  const std::size_t last = simulation.steps.size() - 1;
  for (int k = 1; k <= kNoaBoxes && last > 0; ++k) {
    const std::size_t i = std::max<std::size_t>(1, last * k / kNoaBoxes);
    const std::vector<double>& v = simulation.values[i];
    text += csv_number(simulation.times[i]);
    for (const double q : {0.0, 0.25, 0.5, 0.75, 1.0})
      text += "," + csv_number(sample_quantile(v, q));
    text += "," + csv_number(sample_mean(v)) + "\n";
  }
  return text;
}

// One row per recorded step: the simulation mean and each variant's expected NOA.
std::string curves_csv(const NoaComparison& comparison) {
  std::string text = "time,simulation_mean";
  for (const VariantError& e : comparison.errors) text += "," + e.variant;
  text += "\n";
  const NoaSeries& sim = comparison.simulation;
  for (std::size_t i = 0; i < sim.steps.size(); ++i) {
    text += csv_number(sim.times[i]) + "," + csv_number(sim.mean_at(i));
    for (const NoaSeries& model : comparison.models) {
      const auto at = std::find(model.steps.begin(), model.steps.end(), sim.steps[i]);
      text += "," +
              (at == model.steps.end() ? "" : csv_number(model.mean_at(at - model.steps.begin())));
    }
    text += "\n";
  }
  return text;
}

struct VariantStyle {
  std::string colour, dash, title;
};

// The paper's colours for its variants (original blue, collision orange, its fit dashed),
// then the further hues of plot/variant_colours.hpp.
VariantStyle noa_variant_style(const std::string& variant) {
  if (variant == "original") return {variant_colour(0), "", "Bayindir original"};
  if (variant == "collision") return {variant_colour(1), "", "collision theory (kinetic)"};
  if (variant == kPaperFitVariant)
    return {variant_colour(1), " dt 2", "collision theory (paper fit)"};
  if (variant == kReturnsVariant) return {variant_colour(3), "", "returns (predicted q)"};
  return {variant_colour(2), "", "measured terms"};
}

double box_width(const NoaSeries& simulation) {
  return 0.4 * simulation.times.back() / kNoaBoxes;
}

}  // namespace

void plot_noa(const FigureFiles& files, const std::string& title, const NoaComparison& comparison) {
  write_file_atomic(files.csv("boxes"), boxes_csv(comparison.simulation));
  write_file_atomic(files.csv("curves"), curves_csv(comparison));
  const std::string boxes = gnuplot_quote(files.csv_name("boxes"));
  const std::string curves = gnuplot_quote(files.csv_name("curves"));
  const std::string width = csv_number(box_width(comparison.simulation));
  std::string script = png_preamble(files.size, files.png_name(), title);
  script +=
      "set xlabel 'time (tu)'\nset ylabel 'number of aggregates (NOA)'\nset key bottom right box "
      "opaque\n"
      "set style fill empty\nset yrange [0:*]\n";
  script += "plot " + boxes + " skip 1 using 1:3:2:6:5:(" + width +
            ") with candlesticks whiskerbars lc 'black' title 'simulation (replicates)', \\\n  " +
            boxes + " skip 1 using 1:4:4:4:4:(" + width + ") with candlesticks lc 'black' notitle";
  // One line per variant the comparison holds, in its curves column (3 on).
  for (std::size_t k = 0; k < comparison.errors.size(); ++k) {
    const VariantStyle style = noa_variant_style(comparison.errors[k].variant);
    script += ", \\\n  " + curves + " skip 1 using 1:" + std::to_string(3 + k) +
              " with lines lw 2" + style.dash + " lc rgb '" + style.colour + "' title " +
              gnuplot_quote(style.title);
  }
  script += "\n";
  run_gnuplot(files.script(), script);
}

}  // namespace swarmagg
