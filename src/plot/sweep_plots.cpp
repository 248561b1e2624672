#include "plot/sweep_plots.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "analysis/csv_table.hpp"
#include "analysis/csv_text.hpp"
#include "config/world_keys.hpp"
#include "core/errors.hpp"
#include "models/sample_statistics.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/plot_collection.hpp"
#include "plot/variant_colours.hpp"

namespace swarmagg {
namespace {

struct PointNoa {
  std::vector<std::string> values;  // one per parameter
  double mean = 0.0, half_width = 0.0;
};

bool is_number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

std::vector<PointNoa> read_final_noa(const CsvTable& table, std::size_t parameters) {
  const std::size_t observable = table.column("observable"),
                    replicates = table.column("replicates"), mean = table.column("mean"),
                    sd = table.column("sd");
  std::vector<PointNoa> points;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    if (table.rows[row][observable] != "noa") continue;
    PointNoa point;
    point.values.assign(table.rows[row].begin(),
                        table.rows[row].begin() + static_cast<std::ptrdiff_t>(parameters));
    point.mean = table.number(row, mean);
    const double n = table.number(row, replicates);
    point.half_width =
        n > 1 ? student_t_quantile(n - 1, 0.95) * table.number(row, sd) / std::sqrt(n) : 0.0;
    points.push_back(std::move(point));
  }
  return points;
}

// "k=v, k2=v2" over every parameter but `skip`.
std::string others_label(const std::vector<std::string>& keys, const PointNoa& point,
                         std::size_t skip) {
  std::string label;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (k == skip) continue;
    label += (label.empty() ? "" : ", ") + keys[k] + "=" + point.values[k];
  }
  return label;
}

void plot_against(const std::vector<std::string>& keys, std::size_t p,
                  const std::vector<PointNoa>& points, const FigureFiles& files) {
  std::vector<std::string> xs, series;
  for (const PointNoa& point : points) {
    if (std::find(xs.begin(), xs.end(), point.values[p]) == xs.end()) xs.push_back(point.values[p]);
    const std::string label = others_label(keys, point, p);
    if (std::find(series.begin(), series.end(), label) == series.end()) series.push_back(label);
  }
  const bool numeric = std::all_of(xs.begin(), xs.end(), is_number);
  if (numeric) {
    std::sort(xs.begin(), xs.end(), [](const std::string& a, const std::string& b) {
      return std::stod(a) < std::stod(b);
    });
  }
  std::map<std::pair<std::string, std::string>, const PointNoa*> at;
  for (const PointNoa& point : points) at[{point.values[p], others_label(keys, point, p)}] = &point;

  std::string csv = keys[p];
  for (std::size_t s = 0; s < series.size(); ++s) {
    const std::string n = std::to_string(s);
    csv += ",mean_" + n + ",ci_low_" + n + ",ci_high_" + n;
  }
  csv += "\n";
  for (const std::string& x : xs) {
    csv += x;
    for (const std::string& label : series) {
      const auto found = at.find({x, label});
      if (found == at.end()) {
        csv += ",,,";
        continue;
      }
      const PointNoa& point = *found->second;
      // A NOA is never negative, so neither is the interval's lower end: one below 0 (few
      // replicates) fell outside the plot's y range, and gnuplot then left the whole bar out
      // of the autoscaled range, cutting it at the top too.
      csv += "," + csv_number(point.mean) + "," +
             csv_number(std::max(0.0, point.mean - point.half_width)) + "," +
             csv_number(point.mean + point.half_width);
    }
    csv += "\n";
  }
  write_file_atomic(files.csv(""), csv);

  const std::string data = gnuplot_quote(files.csv_name(""));
  std::string script =
      png_preamble(files.size, files.png_name(),
                   "final NOA against " + keys[p] + ": mean over replicates, 95% CI of the mean");
  script += std::string(kKeyAbovePlot) + "set xlabel " + gnuplot_quote(keys[p]) +
            " noenhanced\nset ylabel 'final number of aggregates (NOA)'\n"
            "set yrange [0:*]\nset offsets graph 0.05, "
            "graph 0.05, 0, 0\n";
  if (numeric && xs.size() > 1 && std::stod(xs.front()) > 0 &&
      std::stod(xs.back()) / std::stod(xs.front()) >= 100) {
    script += "set logscale x\n";  // values spanning decades, as rates often do
  }
  script += "plot ";
  for (std::size_t s = 0; s < series.size(); ++s) {
    const std::size_t mean = 2 + 3 * s;
    const std::string using_x = numeric ? "1" : "0";
    script += (s == 0 ? "" : ", \\\n  ") + data + " skip 1 using " + using_x + ":" +
              std::to_string(mean) + ":" + std::to_string(mean + 1) + ":" +
              std::to_string(mean + 2) + (numeric || s > 0 ? "" : ":xtic(1)") +
              " with yerrorlines lw 2 pt 7 lc rgb " + gnuplot_quote(variant_colour(s)) + " title " +
              gnuplot_quote(series[s].empty() ? "simulation" : series[s]);
  }
  script += "\n";
  run_gnuplot(files.script(), script);
}

}  // namespace

FigureFiles sweep_plot_files(const std::filesystem::path& out, const std::string& key,
                             const PlotSize& size) {
  return {out / kPlotsFolder, "final-noa-vs-" + key, size, ".."};
}

PlotOutcome draw_sweep_plots(const std::filesystem::path& sweep_folder,
                             const std::filesystem::path& out, const PlotSize& size) {
  const auto summary = sweep_folder / kSweepSummaryFile;
  if (!std::filesystem::exists(summary)) {
    throw InputError(sweep_folder.string() + ": holds no merged sweep (no " +
                     std::string(kSweepSummaryFile) + "; run 'swarmagg merge' first)");
  }
  const CsvTable table = read_csv(summary);
  const std::size_t parameters = table.column("observable");
  const std::vector<std::string> keys(
      table.header.begin(), table.header.begin() + static_cast<std::ptrdiff_t>(parameters));
  // Each key names a plot's files: only world keys, so that no name leaves the plots folder.
  for (const std::string& key : keys) {
    if (find_world_key(key) == nullptr) {
      throw InputError(summary.string() + ": column '" + key +
                       "' before 'observable' is not a world key (a merged sweep's parameter "
                       "columns are the keys it swept): the file was edited; merge again");
    }
  }
  const std::vector<PointNoa> points = read_final_noa(table, parameters);
  if (points.empty()) throw InputError(summary.string() + ": has no rows for the observable noa");
  if (const std::string reason = plots_unavailable_reason(); !reason.empty()) {
    throw std::runtime_error("cannot draw plots: " + reason);
  }
  std::filesystem::create_directories(out / kPlotsFolder);
  PlotCollection batch;
  for (std::size_t p = 0; p < keys.size(); ++p) {
    batch.prepare(sweep_plot_files(out, keys[p], size),
                  [&](const FigureFiles& files) { plot_against(keys, p, points, files); });
  }
  return batch.draw();
}

}  // namespace swarmagg
