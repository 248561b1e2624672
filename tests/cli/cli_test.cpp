// Runs the built `swarmagg` binary as a user would and checks exit codes and messages.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_testing.hpp"

namespace {

using ::testing::HasSubstr;

using Outcome = swarmagg::testing::CliOutcome;

Outcome swarmagg(const std::string& arguments) {
  return swarmagg::testing::run_swarmagg(arguments);
}

std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("swarmagg-cli-" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

TEST(Cli, HelpWorksForEverySubcommand) {
  EXPECT_EQ(swarmagg("--help").exit_code, 0);
  for (const char* sub : {"run", "validate"}) {
    const Outcome o = swarmagg(std::string(sub) + " --help");
    EXPECT_EQ(o.exit_code, 0) << sub;
    EXPECT_THAT(o.output, HasSubstr("--set")) << sub;
  }
}

TEST(Cli, ValidatePrintsTheResolvedWorldWithOverrides) {
  const Outcome o = swarmagg("validate worlds/paper/creation-150.yaml --set robots.count=80");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("count: 80"));
  EXPECT_THAT(o.output, HasSubstr("isolated_wait: resume"));
}

TEST(Cli, BadInputExitsTwoWithTheFileAndKey) {
  const Outcome missing = swarmagg("run /nonexistent.yaml");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.output, HasSubstr("/nonexistent.yaml"));
  const Outcome bad = swarmagg("validate worlds/examples/demo.yaml --set robots.radius=-2");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.output, HasSubstr("robots.radius"));
  EXPECT_EQ(swarmagg("run").exit_code, 2);
  EXPECT_EQ(swarmagg("frobnicate").exit_code, 2);
}

TEST(Cli, RunWritesTheOutputFolder) {
  const auto out = temp_dir("run");
  const Outcome o = swarmagg(
      "run worlds/examples/demo.yaml --replicates 2 --threads 2 "
      "--set run.duration=50 --out " +
      out.string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("mean final NOA"));
  EXPECT_TRUE(std::filesystem::exists(out / "timeseries.csv"));
  EXPECT_TRUE(std::filesystem::exists(out / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(out / "world.resolved.yaml"));
  std::filesystem::remove_all(out);
}

}  // namespace
