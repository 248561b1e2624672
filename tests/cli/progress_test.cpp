// Progress outside a terminal: the tests read stderr through a pipe, as a batch or Slurm
// log would, so they see the plain lines (every 10 % or 30 s, and the last one), never the
// live line rewritten with '\r'.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "cli/cli_testing.hpp"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

using Outcome = swarmagg::testing::CliOutcome;

class Progress : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("swarmagg-progress-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Outcome run(const std::string& options) {
    return swarmagg::testing::run_swarmagg(
        "run worlds/examples/demo.yaml --replicates 2 --set robots.count=20 "
        "--set run.duration=300 --force --out " +
        dir_.string() + " " + options);
  }

  fs::path dir_;
};

// "demo: 2/2 replicates  100.0% done  elapsed 0s  eta 0s" on a line of its own.
const std::regex kLastLine(R"((^|\n)demo: 2/2 replicates  100\.0% done  elapsed \d+s  eta 0s\n)");

TEST_F(Progress, ALogGetsPlainLinesWithElapsedDoneAndEta) {
  const Outcome o = run("");
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(std::regex_search(o.output, kLastLine)) << o.output;
  EXPECT_THAT(o.output, Not(HasSubstr("\r")));
  // The phases after the simulation say what they do.
  EXPECT_THAT(o.output, HasSubstr("demo: computing the model predictions"));
  EXPECT_THAT(o.output, HasSubstr("demo: drawing the plots"));
}

TEST_F(Progress, QuietHidesItUnlessAlwaysAndNeverHidesIt) {
  const Outcome quiet = run("--quiet");
  ASSERT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_THAT(quiet.output, Not(HasSubstr("% done")));
  const Outcome always = run("--quiet --progress always");
  ASSERT_EQ(always.exit_code, 0) << always.output;
  EXPECT_TRUE(std::regex_search(always.output, kLastLine)) << always.output;
  const Outcome never = run("--progress never");
  ASSERT_EQ(never.exit_code, 0) << never.output;
  EXPECT_THAT(never.output, Not(HasSubstr("% done")));
  EXPECT_THAT(never.output, Not(HasSubstr("computing the model")));
  EXPECT_EQ(run("--progress sometimes").exit_code, 2);
}

TEST_F(Progress, ASweepInALogSaysHowManyRunsAreDone) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "tiny.yaml") << "name: tiny\nbase: " SWARMAGG_SOURCE_DIR
                                       "/worlds/examples/demo.yaml\n"
                                       "parameters: {robots.count: [10, 20], run.duration: [50]}\n"
                                       "replicates: 2\nseed: 1\n";
  const Outcome o = swarmagg::testing::run_swarmagg("sweep " + (dir_ / "tiny.yaml").string() +
                                                    " --no-plots --out " + (dir_ / "out").string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(
      std::regex_search(o.output, std::regex(R"(tiny: 4/4 runs  100\.0% done  elapsed \d+s)")))
      << o.output;
  EXPECT_THAT(o.output, HasSubstr("merging the runs"));
}

}  // namespace
