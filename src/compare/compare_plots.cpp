#include "compare/compare_plots.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "analysis/csv_text.hpp"
#include "controllers/controller_registry.hpp"
#include "core/time_text.hpp"
#include "models/aggregate_shape.hpp"
#include "models/soysal_rates.hpp"
#include "output/atomic_file.hpp"
#include "plot/drawn_points.hpp"
#include "plot/gnuplot.hpp"
#include "plot/gnuplot_batch.hpp"
#include "rates/poisson_interval.hpp"

namespace swarmagg {
namespace {

std::string noa_script(const std::string& world_name, const ArmResult& a, const ArmResult& b) {
  std::ostringstream gp;
  gp << "# NOA over time of both arms: mean over replicates and its 95% confidence band.\n"
     << "set datafile separator ','\nset terminal pngcairo size 1000,650\nset output 'noa.png'\n"
     << "set title " << gnuplot_quote(world_name + ": NOA, mean and 95% CI of the mean") << "\n"
     << "set xlabel 'time (tu)'\nset ylabel 'number of aggregates'\nset key top left\n"
     << "set style fill transparent solid 0.25 noborder\n"
     << "plot 'noa.csv' skip 1 using 1:3:4 with filledcurves lc rgb '#1f77b4' notitle, \\\n"
     << "     '' skip 1 using 1:2 with lines lw 2 lc rgb '#1f77b4' title " << gnuplot_quote(a.label)
     << ", \\\n"
     << "     '' skip 1 using 1:6:7 with filledcurves lc rgb '#d62728' notitle, \\\n"
     << "     '' skip 1 using 1:5 with lines lw 2 lc rgb '#d62728' title " << gnuplot_quote(b.label)
     << "\n";
  return gp.str();
}

std::string final_script(const std::string& world_name, const Comparison& c) {
  std::ostringstream gp;
  gp << "# Final-state distributions of both arms side by side: final NOA of the replicates\n"
     << "# (left) and the sizes of every final aggregate, pooled over replicates (right).\n"
     << "set datafile separator ','\nset terminal pngcairo size 1300,550\nset output 'final.png'\n"
     << "set multiplot layout 1,2 title " << gnuplot_quote(world_name + ": final state") << "\n"
     << "set style fill solid 0.6 border -1\nset boxwidth 0.4\nset key top right\n"
     << "set ylabel 'replicates'\nset xlabel 'final NOA'\n"
     << "plot 'final_noa.csv' skip 1 using ($1-0.2):2 with boxes lc rgb '#1f77b4' title "
     << gnuplot_quote(c.a.label) << ", \\\n"
     << "     '' skip 1 using ($1+0.2):3 with boxes lc rgb '#d62728' title "
     << gnuplot_quote(c.b.label) << "\n"
     << "set ylabel 'aggregates'\nset xlabel 'final aggregate size'\n";
  if (c.a.final_sizes.empty() && c.b.final_sizes.empty()) {
    // An empty table has no x range to plot over: the panel says why it is empty.
    gp << "set xrange [0:1]\nset yrange [0:1]\nunset xtics\nunset ytics\n"
       << "set label 'no aggregate at the end of any replicate' at graph 0.5, 0.5 center\n"
       << "plot NaN notitle\nunset multiplot\n";
    return gp.str();
  }
  gp << "plot 'sizes.csv' skip 1 using ($1-0.2):2 with boxes lc rgb '#1f77b4' title "
     << gnuplot_quote(c.a.label) << ", \\\n"
     << "     '' skip 1 using ($1+0.2):3 with boxes lc rgb '#d62728' title "
     << gnuplot_quote(c.b.label) << "\nunset multiplot\n";
  return gp.str();
}

// Sizes whose aggregate time gives fewer than this many expected attempts (m p/dt) are left
// out of the plot (they stay in the CSV): their rates are noise.
constexpr double kMinExpectedAttempts = 10.0;

std::string escape_rate_script(const std::string& world_name, const Comparison& c) {
  // A left-out size's interval too: gnuplot scales the axis to the error bars of points
  // whose value is NaN.
  const auto points = [](int time_column, int rate_column) {
    std::string text;
    for (int column = rate_column; column < rate_column + 3; ++column) {
      text += std::string(column > rate_column ? ":" : "") + "($" + std::to_string(time_column) +
              " * $12 >= " + std::to_string(static_cast<int>(kMinExpectedAttempts)) + " ? $" +
              std::to_string(column) + " : NaN)";
    }
    return text;
  };
  std::ostringstream gp;
  gp << "# Escapes per tu per aggregate of size m, pooled over replicates (points: exact 95%\n"
     << "# Poisson interval of the count), with the models' two leave laws. Sizes\n"
     << "# with fewer than " << kMinExpectedAttempts
     << " expected attempts (aggregate_time x m p/dt) are left out.\n"
     << "set datafile separator ','\nset terminal pngcairo size 1000,650\n"
     << "set output 'escape_rate.png'\n"
     << "set title " << gnuplot_quote(world_name + ": escape rate by aggregate size") << "\n"
     << "set xlabel 'aggregate size m'\nset ylabel 'escapes per tu per aggregate'\n"
     << "set key top left\nset xrange [1.5:*]\nset yrange [0:*]\n"
     << "plot 'escape_rate.csv' skip 1 using ($1-0.1):" << points(3, 4)
     << " with yerrorbars pt 7 lc rgb '#1f77b4' title " << gnuplot_quote(c.a.label) << ", \\\n"
     << "     '' skip 1 using ($1+0.1):" << points(8, 9)
     << " with yerrorbars pt 5 lc rgb '#d62728' title " << gnuplot_quote(c.b.label) << ", \\\n"
     << "     '' skip 1 using 1:12 with lines lw 2 dt 2 lc rgb '#444444' title 'm p / dt', \\\n"
     << "     '' skip 1 using 1:13 with lines lw 2 lc rgb '#009e73' title 'periph(m) p / dt'\n";
  return gp.str();
}

// An agent's leave probability per step in an aggregate of `size`, as its controller says.
double member_leave_probability(const WorldSpec& spec, int size) {
  return registration_of(spec.controller.type).leave_probability_at_size(spec, size);
}

// periph(m) as the world's model counts it: Soysal's peripheral variant honours
// model.periphery_cap (the paper worlds leave it off), Bayindir's shrink always caps at m.
double periphery_leavers(const WorldSpec& spec, int size) {
  return controller_rules(spec).model == ModelFamily::Soysal
             ? soysal_leavers(spec, LeavingVariant::Peripheral, size)
             : capped_periphery_agents(size);
}

void write_rate(std::ostringstream& csv, const LeaveTally& leave, int size, double dt) {
  const double exposure = leave.aggregate_time(size, dt);
  const auto k = static_cast<std::size_t>(size);
  const std::int64_t escapes = k < leave.escapes_by_size.size() ? leave.escapes_by_size[k] : 0;
  csv << ',' << escapes << ',' << csv_number(exposure);
  if (exposure <= 0.0) {
    csv << ",NaN,NaN,NaN";
    return;
  }
  // Exact, not the normal approximation: that one's lower end fell below 0 under 4 escapes.
  const PoissonInterval interval = garwood_interval(static_cast<std::uint64_t>(escapes), exposure);
  csv << ',' << csv_number(static_cast<double>(escapes) / exposure) << ','
      << csv_number(interval.low) << ',' << csv_number(interval.high);
}

}  // namespace

std::string escape_rate_csv(const ArmResult& a, const ArmResult& b, const Comparison& c) {
  std::ostringstream csv;
  csv << "size";
  for (const std::string& label : {c.a.label, c.b.label}) {
    csv << ',' << label << "_escapes," << label << "_aggregate_time," << label << "_rate," << label
        << "_ci95_low," << label << "_ci95_high";
  }
  csv << ",all_members_law,periphery_law\n";
  const int largest = std::max(c.a.leave.largest_size(), c.b.leave.largest_size());
  const double dt = a.spec.engine.dt;
  for (int m = 2; m <= largest; ++m) {
    if (c.a.leave.aggregate_time(m, dt) <= 0.0 && c.b.leave.aggregate_time(m, dt) <= 0.0) continue;
    csv << m;
    write_rate(csv, c.a.leave, m, dt);
    write_rate(csv, c.b.leave, m, b.spec.engine.dt);
    const double p_per_tu = member_leave_probability(a.spec, m) / dt;
    csv << ',' << csv_number(m * p_per_tu) << ','
        << csv_number(periphery_leavers(a.spec, m) * p_per_tu) << '\n';
  }
  return csv.str();
}

std::string noa_band_csv(const ArmResult& a, const ArmResult& b, const std::filesystem::path& out) {
  const StepFilter drawn = drawn_steps(a.spec);
  const StepSeries first = read_step_series(out / a.label / "timeseries.csv", "noa", drawn);
  const StepSeries second = read_step_series(out / b.label / "timeseries.csv", "noa", drawn);
  std::ostringstream csv;
  csv << "time," << a.label << "_mean," << a.label << "_low," << a.label << "_high," << b.label
      << "_mean," << b.label << "_low," << b.label << "_high\n";
  auto band = [&csv](const std::vector<double>& replicates) {
    const MeanInterval m = mean_interval(replicates);
    csv << ',' << csv_number(m.mean) << ',' << csv_number(m.mean - m.half_width) << ','
        << csv_number(m.mean + m.half_width);
  };
  // The steps both arms recorded (the same grid: the arms differ in their engine only).
  std::size_t j = 0;
  for (std::size_t i = 0; i < first.steps.size(); ++i) {
    while (j < second.steps.size() && second.steps[j] < first.steps[i]) ++j;
    if (j == second.steps.size()) break;
    if (second.steps[j] != first.steps[i]) continue;
    // The time as the replicates knew it (step * dt) and as their timeseries.csv prints it.
    csv << time_text(static_cast<double>(first.steps[i]) * a.spec.engine.dt);
    band(first.values[i]);
    band(second.values[j]);
    csv << '\n';
  }
  return csv.str();
}

std::string histogram_csv(const std::string& value_name, const std::string& label_a,
                          const std::vector<double>& values_a, const std::string& label_b,
                          const std::vector<double>& values_b) {
  std::map<double, std::pair<int, int>> counts;
  for (double v : values_a) ++counts[v].first;
  for (double v : values_b) ++counts[v].second;
  std::ostringstream csv;
  csv << value_name << ',' << label_a << ',' << label_b << '\n';
  for (const auto& [value, n] : counts)
    csv << csv_number(value) << ',' << n.first << ',' << n.second << '\n';
  return csv.str();
}

std::vector<std::string> write_comparison_plots(const std::string& world_name, const ArmResult& a,
                                                const ArmResult& b, const Comparison& c,
                                                const std::filesystem::path& out) {
  write_file_atomic(out / "noa.csv", noa_band_csv(a, b, out));
  write_file_atomic(out / "final_noa.csv",
                    histogram_csv("final_noa", c.a.label, c.a.final_noa, c.b.label, c.b.final_noa));
  write_file_atomic(out / "sizes.csv",
                    histogram_csv("size", c.a.label, c.a.final_sizes, c.b.label, c.b.final_sizes));
  GnuplotBatch batch;
  run_gnuplot(out / "noa.gp", noa_script(world_name, a, b));
  run_gnuplot(out / "final.gp", final_script(world_name, c));
  // The escape-rate curves are the controller's leave law by aggregate size (Bayindir's,
  // Soysal's), for controllers whose leaving follows from the size.
  if (c.has_leaving && registration_of(a.spec.controller.type).leave_probability_at_size) {
    const std::string rates = escape_rate_csv(a, b, c);
    write_file_atomic(out / "escape_rate.csv", rates);
    // No aggregate of two or more in either arm: no row, nothing to draw.
    if (std::count(rates.begin(), rates.end(), '\n') > 1)
      run_gnuplot(out / "escape_rate.gp", escape_rate_script(world_name, c));
  }
  if (!gnuplot_available()) {
    return {
        "plots skipped: gnuplot is not on PATH (install it with 'sudo apt-get install "
        "gnuplot-nox'; the scripts are beside their CSVs in " +
        out.string() + ": `gnuplot noa.gp` there draws one)"};
  }
  std::vector<std::string> failures;
  for (const GnuplotFailure& failure : batch.draw())
    failures.push_back("cannot draw " + failure.script.string() + ": " + failure.message);
  return failures;
}

}  // namespace swarmagg
