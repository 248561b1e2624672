// noa.png: see run_plot.hpp.
#include <algorithm>
#include <cmath>

#include "analysis/csv_text.hpp"
#include "analysis/model_table.hpp"
#include "analysis/step_series.hpp"
#include "core/counted.hpp"
#include "core/errors.hpp"
#include "models/sample_statistics.hpp"
#include "output/atomic_file.hpp"
#include "plot/drawn_points.hpp"
#include "plot/gnuplot.hpp"
#include "plot/model_curve_lines.hpp"
#include "plot/run_plot.hpp"

namespace swarmagg {
namespace {

// time, mean, ci_low, ci_high, then replicate_<k> per replicate when there are few.
std::string simulation_csv(const StepSeries& noa, bool with_replicates) {
  const std::size_t replicates = noa.values.front().size();
  std::string text = "time,mean,ci_low,ci_high";
  for (std::size_t k = 0; with_replicates && k < replicates; ++k)
    text += ",replicate_" + std::to_string(k);
  text += "\n";
  for (std::size_t i = 0; i < noa.steps.size(); ++i) {
    const MeanInterval m = mean_interval(noa.values[i]);
    text += csv_number(noa.times[i]) + "," + csv_number(m.mean) + "," +
            csv_number(m.mean - m.half_width) + "," + csv_number(m.mean + m.half_width);
    for (std::size_t k = 0; with_replicates && k < replicates; ++k)
      text += "," + csv_number(noa.values[i][k]);
    text += "\n";
  }
  return text;
}

// A model.csv cut short (damaged, or edited since) would draw its curves part of the way, or
// one point, as if the model stopped there.
void check_model_reaches(const std::vector<ModelCurve>& curves, const std::filesystem::path& file,
                         double last_time) {
  for (const ModelCurve& curve : curves) {
    if (std::abs(curve.x.back() - last_time) <= 1e-9 * std::max(1.0, std::abs(last_time))) continue;
    const std::string folder = file.parent_path().empty() ? "." : file.parent_path().string();
    throw InputError(file.string() + ": the model's " + curve.variant + " curve ends at time " +
                     csv_number(curve.x.back()) + ", the run at time " + csv_number(last_time) +
                     (curve.x.back() > last_time
                          ? ": a model of another run; `swarmagg model " + folder +
                                "/world.resolved.yaml --out " + folder + "` gives this run's"
                          : ": cut short or edited since; run the world again"));
  }
}

}  // namespace

void draw_noa_over_time(const RunFiles& run, const FigureFiles& files) {
  const StepSeries noa = read_drawn_series(run, {"noa"}).front();
  const std::size_t replicates = noa.values.front().size();
  const bool thin_lines = replicates > 1 && replicates <= kThinLineReplicates;
  write_file_atomic(files.csv(""), simulation_csv(noa, thin_lines));
  const std::string data = gnuplot_quote(files.csv_name(""));
  std::string script = png_preamble(files.size, files.png_name(),
                                    run_title(run) + ": number of aggregates, " +
                                        std::to_string(run.world.robots.count) + " agents");
  script += std::string(kKeyAbovePlot) +
            "set xlabel 'time (tu)'\nset ylabel 'number of aggregates (NOA)'\n"
            "set yrange [0:*]\n"
            "set style fill transparent solid 0.3 noborder\n";
  script += "plot " + data + " skip 1 using 1:3:4 with filledcurves lc rgb '#7f7f7f' title " +
            gnuplot_quote("95% CI of the mean");
  if (thin_lines) {
    script += ", \\\n  for [k=5:" + std::to_string(4 + replicates) + "] " + data +
              " skip 1 using 1:k with lines lw 0.6 lc rgb '#b0b0b0' title (k == 5 ? "
              "'replicates' : '')";
  }
  script += ", \\\n  " + data + " skip 1 using 1:2 with lines lw 2.5 lc 'black' title " +
            gnuplot_quote("simulation mean (" +
                          counted(static_cast<long long>(replicates), "replicate") + ")");
  if (run.model) {
    const std::vector<ModelCurve> curves = model_curves(*run.model, "noa", drawn_steps(run.world));
    check_model_reaches(curves, *run.model, noa.times.back());
    script += model_curve_lines(curves, files, "model");
  }
  script += "\n";
  run_gnuplot(files.script(), script);
}

}  // namespace swarmagg
