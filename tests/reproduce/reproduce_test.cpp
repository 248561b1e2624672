#include "reproduce/reproduce.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/errors.hpp"
#include "plot/gnuplot.hpp"
#include "plot/png_size.hpp"

namespace swarmagg {
namespace {

// One world of every figure kind, quick and with two replicates: a few seconds in all.
ReproduceOptions reduced_options(const std::filesystem::path& out) {
  ReproduceOptions options;
  options.out = out;
  options.worlds = std::filesystem::path(SWARMAGG_SOURCE_DIR) / "worlds" / "paper";
  options.quick = true;
  options.only = {"collision-count-100", "collision-speed-2", "creation-50", "soysal-5-constant"};
  options.overrides = {"run.replicates=2"};
  options.plot_size = {640, 480};
  options.threads = 2;  // runs side by side, one thread each
  return options;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, '|')) cells.push_back(cell);
  return cells;
}

// The report table row of `world` (its cells between '|', trimmed of spaces).
std::vector<std::string> report_row(const std::string& report, const std::string& world) {
  std::stringstream lines(report);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find("| " + world + " |") == std::string::npos) continue;
    std::vector<std::string> cells;
    for (std::string cell : cells_of(line)) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    return cells;
  }
  return {};
}

// NOA by step of a timeseries-shaped CSV, read independently of the code under test.
std::map<long, std::vector<double>> noa_by_step(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // replicate,step,time,noa,...
  std::map<long, std::vector<double>> noa;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string replicate, step, time, value;
    std::getline(cells, replicate, ',');
    std::getline(cells, step, ',');
    std::getline(cells, time, ',');
    std::getline(cells, value, ',');
    noa[std::stol(step)].push_back(std::stod(value));
  }
  return noa;
}

double mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / v.size();
}

class ReproduceTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!gnuplot_available()) return;
    // CTest runs each test in its own process, several at once: one folder per process.
    out_ = std::filesystem::temp_directory_path() /
           ("swarmagg_reproduce_test_" + std::to_string(::getpid()));
    std::filesystem::remove_all(out_);
    std::ostringstream summary;
    // A throw here would leave every test of the suite "skipped", which CTest counts as not
    // failed: each test fails on it instead.
    try {
      first_ = new ReproduceOutcome(reproduce(reduced_options(out_), summary));
    } catch (const std::exception& e) {
      setup_error_ = e.what();
    }
    summary_ = summary.str();
  }
  static void TearDownTestSuite() {
    delete first_;
    std::filesystem::remove_all(out_);
  }
  void SetUp() override {
    if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
    ASSERT_TRUE(setup_error_.empty()) << "reproduce failed: " << setup_error_;
  }
  static inline std::string setup_error_;
  static inline std::filesystem::path out_;
  static inline ReproduceOutcome* first_ = nullptr;
  static inline std::string summary_;
};

TEST_F(ReproduceTest, EveryFigureIsAPngOfTheRequestedSizeWithItsScriptBesideItsCsv) {
  ASSERT_EQ(first_->figures.size(), 4u);
  for (const FigureResult& r : first_->figures) {
    const auto plots = out_ / "plots";
    const auto size = png_size(plots / (r.figure.id + ".png"));
    ASSERT_TRUE(size.has_value()) << r.figure.id;
    EXPECT_EQ(size->width, 640);
    EXPECT_EQ(size->height, 480);
    const std::string script = read_text(plots / (r.figure.id + ".gp"));
    const auto csv = script.find(r.figure.id + "-");
    ASSERT_NE(csv, std::string::npos) << script;
    const std::string csv_name = script.substr(csv, script.find('\'', csv) - csv);
    EXPECT_TRUE(std::filesystem::exists(plots / csv_name)) << csv_name;
  }
}

TEST_F(ReproduceTest, ReportHasARowPerExperimentAndALinePerClaim) {
  const std::string report = read_text(first_->report);
  for (const char* world :
       {"collision-count-100", "collision-speed-2", "creation-50", "soysal-5-constant"}) {
    EXPECT_FALSE(report_row(report, world).empty()) << world;
  }
  EXPECT_NE(report.find("**Fig 7** encounter frequency vs N overlaps collision theory: **"),
            std::string::npos);
  EXPECT_NE(report.find("**Figs 26-29**"), std::string::npos);
  EXPECT_NE(report.find("not checked"), std::string::npos);  // claims on worlds not run
  EXPECT_EQ(std::count(summary_.begin(), summary_.end(), '\n'), 4);
}

TEST_F(ReproduceTest, EveryImageInTheReportIsAFileBesideIt) {
  const std::string report = read_text(first_->report);
  int images = 0;
  for (auto at = report.find("!["); at != std::string::npos; at = report.find("![", at + 1)) {
    const auto open = report.find("](", at), close = report.find(')', open);
    ASSERT_NE(close, std::string::npos);
    const std::string link = report.substr(open + 2, close - open - 2);
    EXPECT_TRUE(link.starts_with("plots/")) << link;
    EXPECT_TRUE(png_size(first_->report.parent_path() / link).has_value()) << link;
    ++images;
  }
  EXPECT_EQ(images, 4);  // one per figure of reduced_options
  for (const FigureResult& r : first_->figures) {
    // The figure's table rows link to it too.
    EXPECT_NE(report.find("](plots/" + r.figure.id + ".png)"), std::string::npos) << r.figure.id;
  }
}

TEST_F(ReproduceTest, ReportedRmseMatchesTheCsvsItWasComputedFrom) {
  const auto run = out_ / "runs" / "creation-50";
  const auto simulation = noa_by_step(run / "timeseries.csv");
  const auto model = noa_by_step(run / "model-timeseries" / "bayindir-original.csv");
  double squares = 0.0;
  int count = 0;
  for (const auto& [step, values] : simulation) {
    if (!model.count(step)) continue;
    squares += std::pow(mean(values) - model.at(step).front(), 2);
    ++count;
  }
  ASSERT_GT(count, 10);
  const double rmse = std::sqrt(squares / count);
  const auto row = report_row(read_text(first_->report), "creation-50");
  ASSERT_GE(row.size(), 7u);
  // | Fig | world | N | p | final mean NOA | RMSE original | ...: cells[0] is the empty lead.
  EXPECT_NEAR(std::stod(row[6]), rmse, 1e-3 * rmse + 1e-9);
  EXPECT_EQ(row[3], "50");
}

TEST_F(ReproduceTest, ASecondRunReusesEveryRunFolder) {
  std::ostringstream summary;
  const ReproduceOutcome second = reproduce(reduced_options(out_), summary);
  for (const FigureResult& r : second.figures)
    EXPECT_EQ(r.reused, static_cast<int>(r.worlds.size())) << r.figure.id;
  ASSERT_EQ(second.compaction_off.size(), 2u);
  for (const FigureResult& r : second.compaction_off)
    EXPECT_EQ(r.reused, static_cast<int>(r.worlds.size())) << r.figure.id;
}

// CSV value of compaction.csv for (world, compaction, quantity).
std::string compaction_value(const std::string& csv, const std::string& world,
                             const std::string& arm, const std::string& quantity) {
  std::stringstream lines(csv);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string c;
    while (std::getline(stream, c, ',')) cells.push_back(c);
    if (cells.size() >= 4 && cells[1] == world && cells[2] == arm && cells[3] == quantity)
      return cells.size() > 4 ? cells[4] : "";
  }
  return "missing";
}

TEST_F(ReproduceTest, BayindirAndSoysalWorldsAlsoRunWithCompactionOff) {
  // The collision checks have no waiting agents: no second arm for them.
  ASSERT_EQ(first_->compaction_off.size(), 2u);
  EXPECT_EQ(first_->compaction_off[0].figure.id, "fig09-creation-50");
  EXPECT_EQ(first_->compaction_off[1].figure.id, "fig20-21-soysal-5-constant");
  for (const char* world : {"creation-50", "soysal-5-constant"}) {
    const auto on = out_ / "runs" / world / "world.resolved.yaml";
    const auto off = out_ / "compaction-off" / "runs" / world / "world.resolved.yaml";
    EXPECT_NE(read_text(on).find("enabled: true"), std::string::npos) << world;
    EXPECT_NE(read_text(off).find("enabled: false"), std::string::npos) << world;
    EXPECT_TRUE(png_size(out_ / "compaction-off" / "plots" /
                         (world == std::string("creation-50") ? "fig09-creation-50.png"
                                                              : "fig20-21-soysal-5-constant.png"))
                    .has_value())
        << world;
  }
  EXPECT_FALSE(std::filesystem::exists(out_ / "compaction-off" / "runs" / "collision-count-100"));
}

TEST_F(ReproduceTest, CompactionTableHoldsBothArmsOfEachExperiment) {
  const std::string report = read_text(first_->report);
  const std::string csv = read_text(out_ / "compaction.csv");
  ASSERT_NE(report.find("## Compaction on and off"), std::string::npos);
  // | Fig | world | error | original on | original off | second on | off | measured on | off |
  const auto creation =
      report_row(report.substr(report.find("## Compaction on and off")), "creation-50");
  ASSERT_GE(creation.size(), 10u);
  EXPECT_EQ(creation[3], "NOA RMSE");
  // The on column is the error of the report's main table (compaction on is the primary).
  EXPECT_EQ(creation[4], report_row(report, "creation-50")[6]);
  for (std::size_t i = 4; i <= 9; ++i) EXPECT_NO_THROW(std::stod(creation[i])) << creation[i];
  EXPECT_NEAR(std::stod(creation[5]),
              std::stod(compaction_value(csv, "creation-50", "off", "error:original")),
              1e-3 * std::stod(creation[5]) + 1e-9);
  const auto soysal =
      report_row(report.substr(report.find("## Compaction on and off")), "soysal-5-constant");
  ASSERT_GE(soysal.size(), 10u);
  EXPECT_EQ(soysal[3], "TV");
  for (const char* arm : {"on", "off"}) {
    for (const char* world : {"creation-50", "soysal-5-constant"}) {
      EXPECT_NE(compaction_value(csv, world, arm, "error:original"), "missing") << world << arm;
      EXPECT_NE(compaction_value(csv, world, arm, "error:measured"), "missing") << world << arm;
    }
  }
  EXPECT_EQ(compaction_value(csv, "collision-count-100", "on", "error:original"), "missing");
}

// Every CSV under `root`, by its path relative to it.
std::map<std::string, std::string> csv_files(const std::filesystem::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (entry.path().extension() == ".csv")
      files[entry.path().lexically_relative(root).generic_string()] = read_text(entry.path());
  }
  return files;
}

// The summary's lines up to their timing: which figure each line is about, in order.
std::vector<std::string> line_heads(const std::string& summary) {
  std::vector<std::string> heads;
  std::stringstream lines(summary);
  std::string line;
  while (std::getline(lines, line)) heads.push_back(line.substr(0, line.find(" reused")));
  return heads;
}

bool has_file_named(const std::filesystem::path& folder, const std::string& prefix,
                    const std::string& extension) {
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with(prefix) && entry.path().extension() == extension) return true;
  }
  return false;
}

TEST_F(ReproduceTest, OneThreadWritesTheSameFilesAndSummaryAsRunsSideBySide) {
  ReproduceOptions options = reduced_options(out_ / "one-thread");
  options.threads = 1;
  options.run_plots = true;
  std::ostringstream summary;
  reproduce(options, summary);
  const auto side_by_side = csv_files(out_ / "runs");
  const auto one_thread = csv_files(out_ / "one-thread" / "runs");
  ASSERT_FALSE(side_by_side.empty());
  EXPECT_EQ(one_thread, side_by_side);
  EXPECT_EQ(csv_files(out_ / "one-thread" / "compaction-off" / "runs"),
            csv_files(out_ / "compaction-off" / "runs"));
  EXPECT_EQ(line_heads(summary.str()), line_heads(summary_));
  EXPECT_EQ(line_heads(summary_).size(), 4u);  // a line per figure, in the paper's order
  EXPECT_TRUE(line_heads(summary_).front().starts_with("Fig 7 "));
  // Rate plots: scripts by default, drawn with run_plots.
  const auto run = out_ / "runs" / "creation-50";
  EXPECT_TRUE(has_file_named(run, "rates-", ".gp"));
  EXPECT_FALSE(has_file_named(run, "rates-", ".png"));
  EXPECT_TRUE(has_file_named(out_ / "one-thread" / "runs" / "creation-50", "rates-", ".png"));
}

TEST_F(ReproduceTest, AChangedWorldIsRunAgain) {
  ReproduceOptions options = reduced_options(out_ / "changed");
  options.only = {"creation-50"};
  std::ostringstream summary;
  EXPECT_EQ(reproduce(options, summary).figures.front().reused, 0);
  options.overrides.push_back("run.seed=99");
  EXPECT_EQ(reproduce(options, summary).figures.front().reused, 0);
  EXPECT_EQ(reproduce(options, summary).figures.front().reused, 1);
}

// A run's folder given as --out would get REPORT.md among its files and figures in its plots/.
TEST(ReproduceFolder, AFolderHoldingSomethingElseIsRefusedUntouched) {
  const std::filesystem::path out = std::filesystem::temp_directory_path() /
                                    ("swarmagg_reproduce_foreign_" + std::to_string(::getpid()));
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out / "plots");
  std::ofstream(out / "world.resolved.yaml") << "name: mine\n";
  std::ofstream(out / "plots" / "noa.gp") << "plot 1\n";
  std::ostringstream summary;
  try {
    reproduce(reduced_options(out), summary);
    ADD_FAILURE() << "reproduce wrote into a run's folder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds world.resolved.yaml, another command's output"),
              std::string::npos)
        << e.what();
  }
  std::vector<std::string> held;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(out))
    held.push_back(entry.path().lexically_relative(out).string());
  std::sort(held.begin(), held.end());
  EXPECT_EQ(held, (std::vector<std::string>{"plots", "plots/noa.gp", "world.resolved.yaml"}));
  // A sweep's folder holds a runs/ as a reproduction does; your own files, no mark at all.
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out / "runs" / "p0");
  std::ofstream(out / "sweep.json") << "{}\n";
  EXPECT_THROW(reproduce(reduced_options(out), summary), InputError);
  EXPECT_FALSE(std::filesystem::exists(out / "REPORT.md"));
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine\n";
  try {
    reproduce(reduced_options(out), summary);
    ADD_FAILURE() << "reproduce wrote among someone's files";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("holds files but no reproduction"), std::string::npos);
  }
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace swarmagg
