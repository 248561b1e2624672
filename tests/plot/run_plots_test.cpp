// The plots of a run folder and of a merged sweep, drawn from tiny worlds' real outputs.
#include "plot/run_plots.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/csv_table.hpp"
#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "models/predictions.hpp"
#include "plot/drawn_points.hpp"
#include "plot/gnuplot.hpp"
#include "plot/sweep_plots.hpp"
#include "png_pixels.hpp"
#include "run/model_outputs.hpp"
#include "run/placement_sample.hpp"
#include "run/run_folder.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {
namespace {

constexpr PlotSize kSize{640, 400};

std::filesystem::path run_into(const std::string& world, const std::vector<std::string>& overrides,
                               const std::filesystem::path& out) {
  const WorldSpec spec =
      load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/" + world, overrides);
  write_run_folder(spec, run_world(spec, RunOptions{}), out, overrides);
  const std::optional<PlacementSample> sample = placement_start(spec, 1);
  write_model_outputs(spec, pending_predictions(spec, nullptr, sample ? &*sample : nullptr), out);
  return out;
}

std::vector<std::string> names_of(const PlotOutcome& outcome) {
  std::vector<std::string> names;
  for (const auto& png : outcome.drawn) names.push_back(png.filename().string());
  return names;
}

class RunPlotsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!gnuplot_available()) return;
    root_ = std::filesystem::temp_directory_path() /
            ("swarmagg_run_plots_" + std::to_string(::getpid()));
    std::filesystem::remove_all(root_);
    // A throw here would leave every test of the suite "skipped", which CTest counts as not
    // failed: each test fails on it instead.
    try {
      bayindir_ = run_into("examples/demo.yaml",
                           {"robots.count=30", "run.duration=80", "run.replicates=3",
                            "model.stochastic_replicates=2"},
                           root_ / "bayindir");
      soysal_ = run_into("paper/soysal-5-constant.yaml",
                         {"run.duration=2000", "controller.p0=0.002", "run.replicates=2"},
                         root_ / "soysal");
    } catch (const std::exception& e) {
      setup_error_ = e.what();
    }
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(root_); }
  void SetUp() override {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
    ASSERT_TRUE(setup_error_.empty()) << "the runs failed: " << setup_error_;
  }
  static inline std::string setup_error_;
  static inline std::filesystem::path root_, bayindir_, soysal_;
};

void expect_plot_shows_data(const std::filesystem::path& png) {
  const testing::RgbImage image = testing::read_rgb_png(png);
  ASSERT_EQ(image.width, kSize.width) << png;
  ASSERT_EQ(image.height, kSize.height) << png;
  EXPECT_GT(testing::distinct_colours(image), 2u) << png;
  const testing::Frame frame = testing::plot_frame(image);
  ASSERT_LT(frame.left + 100, frame.right) << png;
  ASSERT_LT(frame.top + 100, frame.bottom) << png;
  EXPECT_GT(testing::coloured_pixels_inside(image, frame), 150) << png;
}

TEST_F(RunPlotsTest, ABayindirRunGetsNoaStatesAndSizesWithTheirScriptsAndCsvs) {
  const PlotOutcome outcome = draw_run_plots(bayindir_, bayindir_, kSize);
  EXPECT_TRUE(outcome.failures.empty()) << outcome.failures.front();
  EXPECT_EQ(names_of(outcome), (std::vector<std::string>{"noa.png", "states.png", "sizes.png"}));
  for (const auto& png : outcome.drawn) {
    EXPECT_EQ(png.parent_path(), bayindir_);
    expect_plot_shows_data(png);
    const auto stem = png.stem().string();
    EXPECT_TRUE(std::filesystem::exists(bayindir_ / "plots" / (stem + ".gp"))) << stem;
    EXPECT_TRUE(std::filesystem::exists(bayindir_ / "plots" / (stem + ".csv"))) << stem;
    // The title says the run is not the world file's own: it had overrides.
    std::ifstream script(bayindir_ / "plots" / (stem + ".gp"));
    const std::string text{std::istreambuf_iterator<char>(script), {}};
    EXPECT_NE(text.find("demo (robots.count=30, run.duration=80, run.replicates=3, "
                        "model.stochastic_replicates=2)"),
              std::string::npos)
        << stem;
  }
}

TEST_F(RunPlotsTest, ASoysalRunAlsoGetsItsPartitions) {
  const PlotOutcome outcome = draw_run_plots(soysal_, root_ / "soysal-plots", kSize);
  EXPECT_TRUE(outcome.failures.empty()) << outcome.failures.front();
  EXPECT_EQ(names_of(outcome),
            (std::vector<std::string>{"noa.png", "states.png", "sizes.png", "partitions.png"}));
  for (const auto& png : outcome.drawn) expect_plot_shows_data(png);
  // The partition bars hold the simulation, both paper variants and the returns variant.
  const CsvTable bars = read_csv(root_ / "soysal-plots" / "plots" / "partitions-bars.csv");
  EXPECT_EQ(bars.header, (std::vector<std::string>{"partition", "simulation", "model_original",
                                                   "model_peripheral", "model_returns"}));
}

TEST_F(RunPlotsTest, NoaCsvHoldsTheReplicatesTheirMeanAndABandAroundIt) {
  draw_run_plots(bayindir_, root_ / "noa-check", kSize);
  const CsvTable noa = read_csv(root_ / "noa-check" / "plots" / "noa.csv");
  ASSERT_EQ(noa.header.size(), 4u + 3u);  // time, mean, ci_low, ci_high, 3 replicates
  const CsvTable timeseries = read_csv(bayindir_ / "timeseries.csv");
  ASSERT_EQ(noa.rows.size() * 3, timeseries.rows.size());
  for (std::size_t row = 0; row < noa.rows.size(); ++row) {
    const double mean = noa.number(row, 1);
    EXPECT_NEAR(mean, (noa.number(row, 4) + noa.number(row, 5) + noa.number(row, 6)) / 3, 1e-9);
    EXPECT_LE(noa.number(row, 2), mean);
    EXPECT_GE(noa.number(row, 3), mean);
    // Replicate 1's value is its own timeseries row at that step.
    EXPECT_EQ(noa.number(row, 5), timeseries.number(noa.rows.size() + row, 3));
  }
}

// 12,001 recorded steps: the time plots draw at most kMostDrawnPoints of them, the first and
// the last among them, each with its own value; timeseries.csv keeps them all.
TEST_F(RunPlotsTest, ALongRunsTimePlotsDrawAtMostTheirLimitOfPoints) {
  const std::filesystem::path run =
      run_into("examples/demo.yaml",
               {"robots.count=30", "run.duration=1200", "run.replicates=1", "run.record_every=1",
                "model.stochastic_replicates=1"},
               root_ / "long");
  const PlotOutcome outcome = draw_run_plots(run, run, kSize);
  EXPECT_TRUE(outcome.failures.empty()) << outcome.failures.front();
  const CsvTable timeseries = read_csv(run / "timeseries.csv");
  ASSERT_EQ(timeseries.rows.size(), 12'001u);
  for (const char* csv : {"noa.csv", "noa-model.csv", "states.csv"}) {
    const CsvTable drawn = read_csv(run / "plots" / csv);
    EXPECT_LE(drawn.rows.size(), kMostDrawnPoints) << csv;
    EXPECT_GT(drawn.rows.size(), kMostDrawnPoints / 2) << csv;
    EXPECT_EQ(drawn.number(0, 0), 0.0) << csv;
    EXPECT_EQ(drawn.number(drawn.rows.size() - 1, 0), 1200.0) << csv;
  }
  const CsvTable noa = read_csv(run / "plots" / "noa.csv");
  const std::size_t time = timeseries.column("time"), count = timeseries.column("noa");
  for (std::size_t row = 0, at = 0; row < noa.rows.size(); ++row) {
    while (at < timeseries.rows.size() && timeseries.number(at, time) < noa.number(row, 0)) ++at;
    ASSERT_LT(at, timeseries.rows.size());
    EXPECT_EQ(noa.number(row, 1), timeseries.number(at, count)) << "at time " << noa.number(row, 0);
  }
}

TEST_F(RunPlotsTest, SizesCsvAddsUpToTheFinalNoa) {
  draw_run_plots(bayindir_, root_ / "sizes-check", kSize);
  const CsvTable sizes = read_csv(root_ / "sizes-check" / "plots" / "sizes.csv");
  double aggregates = 0.0;
  for (std::size_t row = 0; row < sizes.rows.size(); ++row) aggregates += sizes.number(row, 1);
  std::ifstream summary(bayindir_ / "summary.json");
  std::stringstream text;
  text << summary.rdbuf();
  const std::string json = text.str();
  const auto at = json.find("\"final_noa\"");
  const auto mean = json.find("\"mean\":", at);
  EXPECT_NEAR(aggregates, std::stod(json.substr(mean + 7)), 1e-9);
  // The model's expected sizes are drawn beside them.
  EXPECT_TRUE(std::filesystem::exists(root_ / "sizes-check" / "plots" / "sizes-model.csv"));
}

TEST_F(RunPlotsTest, ASweepSummaryGivesFinalNoaAgainstEachParameterWithIntervals) {
  const auto sweep = root_ / "sweep";
  std::filesystem::create_directories(sweep);
  std::ofstream(sweep / "sweep_summary.csv")
      << "robots.count,controller.p_leave,observable,replicates,mean,sd,min,q25,median,q75,max\n"
         "30,0.001,noa,4,4,2,1,3,4,5,7\n30,0.001,largest,4,5,1,4,4,5,6,6\n"
         "30,0.005,noa,4,2,2,0,1,2,3,4\n60,0.001,noa,4,9,2,7,8,9,10,11\n"
         "60,0.005,noa,4,6,2,4,5,6,7,8\n";
  const PlotOutcome outcome = draw_sweep_plots(sweep, sweep, kSize);
  EXPECT_EQ(names_of(outcome), (std::vector<std::string>{"final-noa-vs-robots.count.png",
                                                         "final-noa-vs-controller.p_leave.png"}));
  for (const auto& png : outcome.drawn) expect_plot_shows_data(png);
  const CsvTable by_count = read_csv(sweep / "plots" / "final-noa-vs-robots.count.csv");
  ASSERT_EQ(by_count.rows.size(), 2u);
  // mean 4, sd 2, 4 replicates: half-width t(0.975, 3) * 2 / 2 = 3.182.
  EXPECT_NEAR(by_count.number(0, 1), 4.0, 1e-12);
  EXPECT_NEAR(by_count.number(0, 2), 4.0 - 3.18245, 1e-4);
  EXPECT_NEAR(by_count.number(0, 3), 4.0 + 3.18245, 1e-4);
}

// A parameter column names its plot's files: an edited "../../x" column wrote files outside
// the plots folder. Only world keys are taken.
TEST_F(RunPlotsTest, ASweepSummaryColumnThatIsNoWorldKeyIsRefused) {
  const auto sweep = root_ / "sweep-edited" / "deep";
  std::filesystem::create_directories(sweep);
  std::ofstream(sweep / "sweep_summary.csv")
      << "../../../../escaped,observable,replicates,mean,sd,min,q25,median,q75,max\n"
         "30,noa,4,4,2,1,3,4,5,7\n60,noa,4,9,2,7,8,9,10,11\n";
  try {
    draw_sweep_plots(sweep, sweep, kSize);
    ADD_FAILURE() << "a column that is no world key was taken";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("column '../../../../escaped' before 'observable' is not a "
                                   "world key"),
        std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(root_ / "sweep-edited" / "escaped.csv"));
  EXPECT_FALSE(std::filesystem::exists(sweep / "plots"));
}

// A damaged timeseries.csv or model.csv (read row by row while each figure is written) stops
// the plots as bad input naming the file and line, as it did when they were read up front.
TEST_F(RunPlotsTest, ADamagedTimeseriesOrModelCsvIsBadInputNamingItsLine) {
  for (const char* damaged : {"timeseries.csv", "model.csv"}) {
    const std::filesystem::path copy = root_ / (std::string("damaged-") + damaged);
    std::filesystem::copy(bayindir_, copy, std::filesystem::copy_options::recursive);
    // The last row replaced, not one added: a timeseries.csv with a row too many or too few
    // is refused before any line is read (holds_every_row).
    std::string text;
    {
      std::ifstream in(copy / damaged);
      text.assign(std::istreambuf_iterator<char>(in), {});
    }
    text.erase(text.rfind('\n', text.size() - 2) + 1);
    std::ofstream(copy / damaged, std::ios::trunc) << text << "0,1\n";
    try {
      draw_run_plots(copy, copy, kSize);
      ADD_FAILURE() << damaged << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find((copy / damaged).string() + ":"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("fields as the header has"), std::string::npos)
          << e.what();
    }
  }
}

// summary.json edited or damaged: what the plots read of it (each replicate's final sizes, the
// overrides) is checked against the world, and refused naming the file and the key. A size
// out of range was an index past the end of the sizes plot's counts (a crash); a damaged
// structure was a JSON library's message that named no file.
TEST_F(RunPlotsTest, ADamagedSummaryIsBadInputNamingItsKey) {
  const std::string sizes = "replicates[1].final.aggregate_sizes";
  const std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>> damages = {
      {[](nlohmann::json& j) { j["replicates"][1]["final"]["aggregate_sizes"] = {-5}; }, sizes},
      {[](nlohmann::json& j) { j["replicates"][1]["final"]["aggregate_sizes"] = {2147483647}; },
       sizes},
      {[](nlohmann::json& j) { j["replicates"][1]["final"]["aggregate_sizes"] = {31}; }, sizes},
      {[](nlohmann::json& j) {
         j["replicates"][1]["final"]["aggregate_sizes"] = std::vector<int>(16, 2);
       },
       sizes},
      {[](nlohmann::json& j) { j["replicates"][1]["final"]["aggregate_sizes"] = {2.5}; }, sizes},
      {[](nlohmann::json& j) { j["replicates"][1]["final"].erase("aggregate_sizes"); }, sizes},
      {[](nlohmann::json& j) { j["replicates"].erase(2); }, "replicates: expected a list of 3"},
      {[](nlohmann::json& j) { j = nlohmann::json::object(); }, "replicates: expected a list of 3"},
      {[](nlohmann::json& j) { j["overrides"] = {1}; }, "overrides: expected a list of texts"},
  };
  int case_number = 0;
  for (const auto& [damage, key] : damages) {
    const std::filesystem::path copy = root_ / ("damaged-summary-" + std::to_string(++case_number));
    std::filesystem::copy(bayindir_, copy, std::filesystem::copy_options::recursive);
    nlohmann::json summary;
    std::ifstream(copy / "summary.json") >> summary;
    damage(summary);
    std::ofstream(copy / "summary.json", std::ios::trunc) << summary.dump();
    try {
      draw_run_plots(copy, copy, kSize);
      ADD_FAILURE() << "case " << case_number << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find((copy / "summary.json").string() + ": " + key),
                std::string::npos)
          << e.what();
    }
  }
  // A replicate that ends with no aggregate, and one whose aggregates hold every agent, are
  // runs as they come.
  const std::filesystem::path edge = root_ / "summary-edges";
  std::filesystem::copy(bayindir_, edge, std::filesystem::copy_options::recursive);
  nlohmann::json summary;
  std::ifstream(edge / "summary.json") >> summary;
  summary["replicates"][0]["final"]["aggregate_sizes"] = nlohmann::json::array();
  summary["replicates"][1]["final"]["aggregate_sizes"] = {30};
  std::ofstream(edge / "summary.json", std::ios::trunc) << summary.dump();
  EXPECT_NO_THROW(draw_run_plots(edge, edge, kSize));
}

TEST_F(RunPlotsTest, ARunWithoutItsTimeseriesIsBadInput) {
  const std::filesystem::path copy = root_ / "no-timeseries";
  std::filesystem::copy(bayindir_, copy, std::filesystem::copy_options::recursive);
  std::filesystem::remove(copy / "timeseries.csv");
  EXPECT_THROW(draw_run_plots(copy, copy, kSize), InputError);
  std::filesystem::create_directory(copy / "timeseries.csv");
  EXPECT_THROW(draw_run_plots(copy, copy, kSize), InputError);
}

TEST_F(RunPlotsTest, AFolderWithoutARunIsBadInput) {
  EXPECT_THROW(draw_run_plots(root_ / "nothing-here", root_ / "nothing-here"), InputError);
  EXPECT_THROW(draw_sweep_plots(root_ / "nothing-here", root_ / "nothing-here"), InputError);
}

}  // namespace
}  // namespace swarmagg
