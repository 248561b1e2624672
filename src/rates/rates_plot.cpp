#include "rates/rates_plot.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "analysis/csv_text.hpp"
#include "models/kinetic_rate.hpp"
#include "output/atomic_file.hpp"
#include "output/format_text.hpp"
#include "plot/gnuplot.hpp"
#include "plot/gnuplot_batch.hpp"
#include "plot/png_terminal.hpp"
#include "rates/geometry_fits.hpp"

namespace swarmagg {

namespace {

const char* const kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728"};

std::string optional_text(const std::optional<double>& value) {
  return value ? csv_number(*value) : "";
}

std::string term_label(const std::string& term) {
  if (term == "creation" || term == "pairup") return "per searcher pair per tu";
  if (term == "growth" || term == "join" || term == "join_new")
    return "per searcher per aggregate per tu";
  if (term == "return") return "fraction of LEAVE attempts that return";
  if (term == "return_time") return "mean time away of a return (tu)";
  if (term == "attempt" || term == "escape") return "per aggregate per tu";
  if (term == "radius") return "mean outer radius R1 (u)";
  if (term == "rim") return "mean rim members";
  return "aggregates per replicate after the first decision";
}

std::vector<std::string> variants_of(const std::vector<const RateRow*>& rows) {
  std::vector<std::string> names;
  for (const RateRow* row : rows) {
    for (const ModelTerm& m : row->models) {
      const std::string name = m.model + " " + m.variant;
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  return names;
}

void plot_sized(const std::string& term, const std::vector<const RateRow*>& rows,
                const std::filesystem::path& folder, const WorldSpec& world) {
  const std::vector<std::string> variants = variants_of(rows);
  std::string csv = "size,rate,ci_low,ci_high";
  for (const std::string& v : variants) csv += "," + v;
  csv += "\n";
  for (const RateRow* row : rows) {
    csv += std::to_string(*row->size) + "," + optional_text(row->estimate.rate) + "," +
           optional_text(row->estimate.low) + "," + optional_text(row->estimate.high);
    for (const std::string& v : variants) {
      std::string value;
      for (const ModelTerm& m : row->models)
        if (m.model + " " + m.variant == v) value = csv_number(m.rate);
      csv += "," + value;
    }
    csv += "\n";
  }
  const std::string name = "rates-" + term;
  write_file_atomic(folder / (name + ".csv"), csv);
  const std::string data = gnuplot_quote(name + ".csv");
  std::string script = png_preamble({}, name + ".png", world.name + ": measured " + term);
  script += "set xlabel 'aggregate size m'\nset ylabel " + gnuplot_quote(term_label(term)) +
            "\nset key top left box opaque\nset yrange [0:*]\nset offsets 0.5, 0.5, 0, 0\n";
  script += "plot " + data +
            " skip 1 using 1:2:3:4 with yerrorbars pt 7 lc 'black' title 'simulation (95% CI)'";
  for (std::size_t k = 0; k < variants.size(); ++k) {
    script += ", \\\n  " + data + " skip 1 using 1:" + std::to_string(5 + k) +
              " with linespoints lw 2 lc rgb '" + kColours[k % 4] + "' title " +
              gnuplot_quote(variants[k]);
  }
  script += "\n";
  run_gnuplot(folder / (name + ".gp"), script);
}

// A term without sizes: the measurement and each model's value as points side by side.
void plot_single(const WorldSpec& world, const RateRow& row, const std::filesystem::path& folder) {
  std::vector<std::pair<std::string, double>> values;
  for (const ModelTerm& m : row.models) values.emplace_back(m.model + " " + m.variant, m.rate);
  if (row.term == "creation") {
    // The paper's fitted Z = C s v N^2 (formula (6) times A^2) per pair: 2 C s v.
    values.emplace_back("paper fit", 2.0 * kPaperCollisionConstant * world.robots.detection_radius *
                                         world.robots.speed);
  }
  std::string csv = "x,label,value,ci_low,ci_high\n";
  csv += "1,simulation," + optional_text(row.estimate.rate) + "," +
         optional_text(row.estimate.low) + "," + optional_text(row.estimate.high) + "\n";
  std::string xtics = "'simulation' 1";
  for (std::size_t k = 0; k < values.size(); ++k) {
    const std::string x = std::to_string(k + 2);
    csv += x + "," + values[k].first + "," + csv_number(values[k].second) + "," +
           csv_number(values[k].second) + "," + csv_number(values[k].second) + "\n";
    xtics += ", " + gnuplot_quote(values[k].first) + " " + x;
  }
  const std::string name = "rates-" + row.term;
  write_file_atomic(folder / (name + ".csv"), csv);
  std::string script = png_preamble({}, name + ".png", world.name + ": measured " + row.term);
  script += "set ylabel " + gnuplot_quote(term_label(row.term)) + "\nset xtics (" + xtics +
            ")\nset xrange [0.5:" + std::to_string(values.size() + 1) +
            ".5]\nset yrange [0:*]\nunset key\n";
  script += "plot " + gnuplot_quote(name + ".csv") +
            " skip 1 using 1:3:4:5 with yerrorbars pt 7 ps 1.5 lc 'black'\n";
  run_gnuplot(folder / (name + ".gp"), script);
}

// The radius and rim rows with the fitted law as one more curve beside the models'.
std::vector<RateRow> with_geometry_fits(const WorldSpec& world, const std::vector<RateRow>& rows) {
  const GeometryFits fits = fit_geometry_laws(rows, world.robots.radius);
  std::vector<RateRow> plotted = rows;
  for (RateRow& row : plotted) {
    const PowerLawFit* fit = row.term == "radius" ? &fits.radius
                             : row.term == "rim"  ? &fits.rim
                                                  : nullptr;
    if (!fit || !fit->fitted() || !row.size) continue;
    const double power = fit->a->value * std::pow(*row.size, fit->b->value);
    const double value =
        row.term == "radius" ? world.robots.radius * power : std::numbers::pi * (power - 1.0);
    row.models.push_back(
        {"fit", format_text("a=%.3g b=%.3g", fit->a->value, fit->b->value), value});
  }
  return plotted;
}

// Writes each term's CSV and script; run_gnuplot queues them in the caller's batch.
void write_scripts(const WorldSpec& world, const std::vector<RateRow>& measured,
                   const std::filesystem::path& folder) {
  const std::vector<RateRow> rows = with_geometry_fits(world, measured);
  std::map<std::string, std::vector<const RateRow*>> sized;
  for (const RateRow& row : rows) {
    if (row.size) {
      sized[row.term].push_back(&row);
    } else {
      plot_single(world, row, folder);
    }
  }
  for (const auto& [term, term_rows] : sized) {
    // Nothing to draw (a short run: too few returns to time, and no model): no plot.
    const bool drawable = std::any_of(term_rows.begin(), term_rows.end(), [](const RateRow* r) {
      return r->estimate.rate || !r->models.empty();
    });
    if (drawable) plot_sized(term, term_rows, folder, world);
  }
}

}  // namespace

void write_rate_plot_scripts(const WorldSpec& world, const std::vector<RateRow>& rows,
                             const std::filesystem::path& folder) {
  const GnuplotBatch undrawn;  // closed without drawing: the scripts stay, no PNG is drawn
  write_scripts(world, rows, folder);
}

void plot_rates(const WorldSpec& world, const std::vector<RateRow>& rows,
                const std::filesystem::path& folder) {
  GnuplotBatch batch;
  write_scripts(world, rows, folder);
  batch.draw_or_throw();
}

}  // namespace swarmagg
