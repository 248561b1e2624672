#include "plot/sweep_plots.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "analysis/csv_table.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

// Two replicates far apart: the mean's 95% interval, 1.5 +- 12.706 * 2 / sqrt(2), reaches
// below 0, which no NOA can; the plot's data cut it there, as gnuplot left such a bar out of
// the y range (it showed the axis up to the other point only).
TEST(SweepPlots, TheIntervalOfAMeanNoaStopsAtZero) {
  const testing::ScratchDir scratch("sweep-plots");
  std::ofstream(scratch.path() / kSweepSummaryFile)
      << "controller.p_leave,observable,replicates,mean,sd,min,q25,median,q75,max\n"
         "0.001,noa,2,1.5,2,0,0.75,1.5,2.25,3\n"
         "0.002,noa,2,5,0,5,5,5,5,5\n";
  draw_sweep_plots(scratch.path(), scratch.path());  // no gnuplot: the CSV is written all the same
  const CsvTable table = read_csv(sweep_plot_files(scratch.path(), "controller.p_leave").csv(""));
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_EQ(table.number(0, table.column("ci_low_0")), 0.0);
  EXPECT_NEAR(table.number(0, table.column("ci_high_0")), 1.5 + 12.7062047 * 2 / std::sqrt(2.0),
              1e-5);
  EXPECT_EQ(table.number(1, table.column("ci_low_0")), 5.0);
}

}  // namespace
}  // namespace swarmagg
