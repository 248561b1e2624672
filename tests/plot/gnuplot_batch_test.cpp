#include "plot/gnuplot_batch.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "plot/gnuplot.hpp"
#include "plot/png_size.hpp"
#include "plot/png_terminal.hpp"

namespace swarmagg {
namespace {

std::filesystem::path fresh_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() /
                      ("swarmagg_batch_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Two figures that set different styles: the second must not inherit the first's.
std::string first_script() {
  return png_preamble(PlotSize{320, 200}, "first.png", "first") +
         "set logscale y\nset xrange [0:5]\nf(x) = 3 * x\n"
         "plot 'data.csv' skip 1 using 1:2 with points pt 7, f(x)\n";
}
std::string second_script() {
  return png_preamble(PlotSize{240, 160}, "second.png", "second") +
         "plot 'data.csv' skip 1 using 1:2 with lines\n";
}

void write_data(const std::filesystem::path& folder) {
  std::ofstream(folder / "data.csv") << "x,y\n1,2\n2,4\n3,5\n";
}

TEST(GnuplotBatch, DrawsEachFigureAsGnuplotDrawsItAlone) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto alone = fresh_folder("alone");
  const auto batched_a = fresh_folder("batched_a");
  const auto batched_b = fresh_folder("batched_b");
  for (const auto& folder : {alone, batched_a, batched_b}) write_data(folder);
  run_gnuplot(alone / "first.gp", first_script());
  run_gnuplot(alone / "second.gp", second_script());
  {
    GnuplotBatch batch;
    run_gnuplot(batched_a / "first.gp", first_script());  // each from its own folder
    run_gnuplot(batched_b / "second.gp", second_script());
    EXPECT_FALSE(std::filesystem::exists(batched_a / "first.png")) << "drawn before draw()";
    EXPECT_TRUE(batch.draw().empty());
  }
  EXPECT_EQ(bytes_of(batched_a / "first.png"), bytes_of(alone / "first.png"));
  EXPECT_EQ(bytes_of(batched_b / "second.png"), bytes_of(alone / "second.png"));
  EXPECT_EQ(png_size(batched_b / "second.png")->width, 240);
}

TEST(GnuplotBatch, AFailingScriptIsNamedAndTheOthersAreDrawn) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("failing");
  write_data(folder);
  GnuplotBatch batch;
  run_gnuplot(folder / "first.gp", first_script());
  run_gnuplot(folder / "bad.gp", png_preamble(PlotSize{100, 100}, "bad.png", "bad") +
                                     "plot 'no-such-file.csv' using 1:2\n");
  run_gnuplot(folder / "second.gp", second_script());
  const std::vector<GnuplotFailure> failures = batch.draw();
  ASSERT_EQ(failures.size(), 1u);
  EXPECT_EQ(failures.front().script, folder / "bad.gp");
  EXPECT_NE(failures.front().message.find("no-such-file.csv"), std::string::npos)
      << failures.front().message;
  EXPECT_TRUE(png_size(folder / "first.png").has_value());
  EXPECT_TRUE(png_size(folder / "second.png").has_value());
  EXPECT_THROW(
      {
        run_gnuplot(folder / "bad.gp", "plot 'no-such-file.csv' using 1:2\n");
        batch.draw_or_throw();
      },
      std::runtime_error);
}

// gnuplot empties a PNG when its script names it: a script that then fails would leave an
// empty plot where a good one was. The plot is the earlier one or the new one, whole, and
// nothing hidden stays beside it.
TEST(GnuplotBatch, AFailedScriptLeavesTheEarlierPlotWhole) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("atomic");
  write_data(folder);
  run_gnuplot(folder / "first.gp", first_script());
  const std::string earlier = bytes_of(folder / "first.png");
  ASSERT_TRUE(png_size(folder / "first.png").has_value());
  const std::string failing = png_preamble(PlotSize{100, 100}, "first.png", "failing") +
                              "plot 'no-such-file.csv' using 1:2\n";
  try {
    run_gnuplot(folder / "failing.gp", failing);
    ADD_FAILURE() << "a failing script must throw";
  } catch (const std::runtime_error& e) {
    // gnuplot's words name the user's script, not the hidden copy it ran.
    EXPECT_NE(std::string(e.what()).find("\"failing.gp\" line"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find(".tmp"), std::string::npos) << e.what();
  }
  EXPECT_EQ(bytes_of(folder / "first.png"), earlier);
  {
    GnuplotBatch batch;
    run_gnuplot(folder / "failing.gp", failing);
    EXPECT_EQ(batch.draw().size(), 1u);
  }
  EXPECT_EQ(bytes_of(folder / "first.png"), earlier);
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
  // The script the user keeps names the PNG itself, to be run again by hand.
  EXPECT_NE(bytes_of(folder / "failing.gp").find("set output 'first.png'"), std::string::npos);
}

TEST(GnuplotBatch, ABatchClosedUndrawnLeavesTheScriptsAndDrawsNothing) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("undrawn");
  write_data(folder);
  {
    const GnuplotBatch undrawn;
    run_gnuplot(folder / "first.gp", first_script());
  }
  EXPECT_TRUE(std::filesystem::exists(folder / "first.gp"));
  EXPECT_FALSE(std::filesystem::exists(folder / "first.png"));
  run_gnuplot(folder / "second.gp", second_script());  // no batch open: drawn at once
  EXPECT_TRUE(png_size(folder / "second.png").has_value());
}

TEST(GnuplotBatch, AnInnerBatchDrawsItsOwnScriptsAndTheOuterOneItsOwn) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const auto folder = fresh_folder("nested");
  write_data(folder);
  GnuplotBatch outer;
  run_gnuplot(folder / "first.gp", first_script());
  {
    GnuplotBatch inner;
    run_gnuplot(folder / "second.gp", second_script());
    EXPECT_TRUE(inner.draw().empty());
  }
  EXPECT_TRUE(png_size(folder / "second.png").has_value());
  EXPECT_FALSE(std::filesystem::exists(folder / "first.png"));
  EXPECT_TRUE(outer.draw().empty());
  EXPECT_TRUE(png_size(folder / "first.png").has_value());
}

}  // namespace
}  // namespace swarmagg
