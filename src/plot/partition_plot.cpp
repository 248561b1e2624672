#include "plot/partition_plot.hpp"

#include <algorithm>
#include <set>

#include "analysis/csv_text.hpp"
#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "plot/variant_colours.hpp"

namespace swarmagg {
namespace {

double probability(const Distribution& d, const std::string& key) {
  const auto found = d.find(key);
  return found == d.end() ? 0.0 : found->second;
}

// Every partition any source gives, most likely first (by its largest probability).
std::vector<std::string> ranked_partitions(const PartitionComparison& c) {
  std::set<std::string> keys;
  for (const auto& [k, v] : c.simulation) keys.insert(k);
  for (const Distribution& d : c.models) {
    for (const auto& [k, v] : d) keys.insert(k);
  }
  auto peak = [&](const std::string& key) {
    double best = probability(c.simulation, key);
    for (const Distribution& d : c.models) best = std::max(best, probability(d, key));
    return best;
  };
  std::vector<std::string> ranked(keys.begin(), keys.end());
  std::stable_sort(ranked.begin(), ranked.end(),
                   [&](const std::string& a, const std::string& b) { return peak(a) > peak(b); });
  return ranked;
}

}  // namespace

void plot_partitions(const FigureFiles& files, const std::string& title,
                     const PartitionComparison& comparison) {
  std::string csv = "partition,simulation";
  for (const VariantError& e : comparison.errors) csv += ",model_" + e.variant;
  csv += "\n";
  for (const std::string& key : ranked_partitions(comparison)) {
    csv += key + "," + csv_number(probability(comparison.simulation, key));
    for (const Distribution& d : comparison.models) csv += "," + csv_number(probability(d, key));
    csv += "\n";
  }
  write_file_atomic(files.csv("bars"), csv);
  const std::string data = gnuplot_quote(files.csv_name("bars"));
  const std::string rows = "every ::0::" + std::to_string(kPartitionBars - 1);
  std::string script = png_preamble(files.size, files.png_name(), title);
  script +=
      "set ylabel 'fraction of time'\nset xlabel 'partition'\nset key top right\n"
      "set style data histograms\nset style histogram clustered gap 1\n"
      "set style fill solid 0.8 border -1\nset xtics rotate by -45 noenhanced\nset yrange [0:*]\n";
  script += "plot " + data + " skip 1 " + rows + " using 2:xtic(1) lc 'black' title 'simulation'";
  for (std::size_t k = 0; k < comparison.errors.size(); ++k) {
    script += ", \\\n  " + data + " skip 1 " + rows + " using " + std::to_string(k + 3) +
              " lc rgb " + gnuplot_quote(variant_colour(k)) + " title " +
              gnuplot_quote("model " + comparison.errors[k].variant);
  }
  script += "\n";
  run_gnuplot(files.script(), script);
}

}  // namespace swarmagg
