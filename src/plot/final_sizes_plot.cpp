// sizes.png: see run_plot.hpp.
#include <algorithm>

#include "analysis/csv_text.hpp"
#include "analysis/model_table.hpp"
#include "core/counted.hpp"
#include "models/model_series.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/model_curve_lines.hpp"
#include "plot/run_plot.hpp"

namespace swarmagg {
namespace {

// Model sizes expected fewer times than this are off the plot's right end (the CSV of the
// model keeps only what is drawn; model.csv has them all).
constexpr double kDrawnAggregates = 0.01;

}  // namespace

void draw_final_sizes(const RunFiles& run, const FigureFiles& files) {
  const std::vector<std::vector<int>>& sizes = run.final_sizes;
  std::vector<ModelCurve> model;
  if (run.model)
    model = model_curves_by_suffix(*run.model, kAggregatesOfSize, run.world.robots.count);
  int largest = 2;
  for (const auto& replicate : sizes) {
    for (const int m : replicate) largest = std::max(largest, m);
  }
  for (const ModelCurve& curve : model) {
    for (std::size_t i = 0; i < curve.x.size(); ++i) {
      if (curve.y[i] >= kDrawnAggregates) largest = std::max(largest, static_cast<int>(curve.x[i]));
    }
  }
  for (ModelCurve& curve : model) {
    for (std::size_t i = curve.x.size(); i-- > 0;) {
      if (curve.x[i] > largest) {
        curve.x.erase(curve.x.begin() + static_cast<std::ptrdiff_t>(i));
        curve.y.erase(curve.y.begin() + static_cast<std::ptrdiff_t>(i));
      }
    }
  }
  std::vector<double> mean_count(static_cast<std::size_t>(largest) + 1, 0.0);
  for (const auto& replicate : sizes) {
    for (const int m : replicate) mean_count[static_cast<std::size_t>(m)] += 1.0;
  }
  std::string csv = "size,mean_aggregates\n";
  for (int m = 2; m <= largest; ++m) {
    csv += std::to_string(m) + "," +
           csv_number(mean_count[static_cast<std::size_t>(m)] / static_cast<double>(sizes.size())) +
           "\n";
  }
  write_file_atomic(files.csv(""), csv);

  const std::string data = gnuplot_quote(files.csv_name(""));
  const double end_time = run.world.run.duration;
  std::string script = png_preamble(
      files.size, files.png_name(),
      run_title(run) + ": aggregate sizes at the end (t = " + csv_number(end_time) +
          " tu), mean of " + counted(static_cast<long long>(sizes.size()), "replicate"));
  script += std::string(kKeyAbovePlot) +
            "set xlabel 'aggregate size (agents)'\nset ylabel 'aggregates of that size'\n"
            "set yrange [0:*]\nset xrange [1.5:" +
            std::to_string(largest) +
            ".5]\nset xtics 1\nset boxwidth 0.7\n"
            "set style fill solid 0.5 border -1\n";
  if (largest > 30) script += "set xtics autofreq\n";
  script += "plot " + data + " skip 1 using 1:2 with boxes lc rgb '#7f7f7f' title 'simulation'";
  script += model_curve_lines(model, files, "model", "linespoints lw 2 pt 7 ps 1.2", 0.0);
  script += "\n";
  run_gnuplot(files.script(), script);
}

}  // namespace swarmagg
