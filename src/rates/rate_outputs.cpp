#include "rates/rate_outputs.hpp"

#include <iostream>

#include "output/atomic_file.hpp"
#include "plot/gnuplot.hpp"
#include "rates/rates_csv.hpp"
#include "rates/rates_json.hpp"
#include "rates/rates_plot.hpp"

namespace swarmagg {

void write_rate_outputs(const WorldSpec& world, const RateTally& tally,
                        const std::vector<RateRow>& rows, const std::filesystem::path& folder,
                        RatePlots plots) {
  std::filesystem::create_directories(folder);
  write_file_atomic(folder / "rates.csv", rates_csv(rows));
  write_file_atomic(folder / "rates.json", rates_json(world, tally, rows));
  if (plots == RatePlots::Draw && gnuplot_available()) {
    plot_rates(world, rows, folder);
    return;
  }
  // The scripts and their CSVs still go beside rates.csv: gnuplot, once installed, draws them.
  write_rate_plot_scripts(world, rows, folder);
  if (plots == RatePlots::Draw) {
    std::cerr << "note: gnuplot not found: rate plots not drawn (install gnuplot-nox; the "
                 "rates-<term>.gp scripts are beside rates.csv)\n";
  }
}

}  // namespace swarmagg
