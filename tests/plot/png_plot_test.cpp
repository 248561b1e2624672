#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "plot/gnuplot.hpp"
#include "plot/png_size.hpp"
#include "plot/png_terminal.hpp"

namespace swarmagg {
namespace {

std::filesystem::path fresh_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("swarmagg_plot_" + name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

TEST(PngPlot, GnuplotDrawsAPngOfTheRequestedSizeFromACsvBesideTheScript) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("size");
  std::ofstream(folder / "data.csv") << "x,y\n1,2\n2,4\n3,5\n";
  const std::string script = png_preamble(PlotSize{320, 200}, "out.png", "a \"quoted\" title") +
                             "plot 'data.csv' skip 1 using 1:2 with lines\n";
  run_gnuplot(folder / "out.gp", script);
  EXPECT_TRUE(std::filesystem::exists(folder / "out.gp"));
  const auto size = png_size(folder / "out.png");
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->width, 320);
  EXPECT_EQ(size->height, 200);
}

TEST(PngPlot, AScriptPathRelativeToTheWorkingDirectoryWorks) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("relative");
  std::filesystem::create_directories(folder / "plots");
  std::ofstream(folder / "plots" / "data.csv") << "x,y\n1,2\n2,4\n";
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(folder);
  EXPECT_NO_THROW(
      run_gnuplot("plots/rel.gp", png_preamble(PlotSize{200, 100}, "rel.png", "relative") +
                                      "plot 'data.csv' skip 1 using 1:2 with lines\n"));
  std::filesystem::current_path(previous);
  EXPECT_TRUE(png_size(folder / "plots" / "rel.png").has_value());
}

TEST(PngPlot, PngSizeRejectsFilesThatAreNotPngs) {
  const auto folder = fresh_folder("reject");
  std::ofstream(folder / "not.png") << "this is text, not an image, long enough to hold a header";
  EXPECT_FALSE(png_size(folder / "not.png").has_value());
  EXPECT_FALSE(png_size(folder / "missing.png").has_value());
}

// A PNG cut short (a full disk) is told from a whole one by its missing IEND chunk.
TEST(PngPlot, PngCompleteTellsAWholeFileFromATruncatedOne) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("complete");
  std::ofstream(folder / "data.csv") << "x,y\n1,2\n2,4\n";
  run_gnuplot(folder / "whole.gp", png_preamble(PlotSize{200, 100}, "whole.png", "whole") +
                                       "plot 'data.csv' skip 1 using 1:2 with lines\n");
  EXPECT_TRUE(png_complete(folder / "whole.png"));
  const auto size = std::filesystem::file_size(folder / "whole.png");
  std::filesystem::copy_file(folder / "whole.png", folder / "cut.png");
  std::filesystem::resize_file(folder / "cut.png", size - 20);
  EXPECT_TRUE(png_size(folder / "cut.png").has_value());  // its start is a PNG's
  EXPECT_FALSE(png_complete(folder / "cut.png"));
  EXPECT_FALSE(png_complete(folder / "missing.png"));
}

TEST(PngPlot, GnuplotErrorsCarryGnuplotsMessage) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("error");
  try {
    run_gnuplot(folder / "bad.gp", "plot 'no-such-file.csv' using 1:2\n");
    FAIL() << "gnuplot should have failed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no-such-file.csv"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarmagg
