// `swarmagg keys` and `swarmagg help`, which print docs/reference/world-keys.md and
// docs/reference/cli.md (tests/docs/check_reference.sh compares the pages with them).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_testing.hpp"
#include "config/world_keys.hpp"

namespace {

using swarmagg::testing::run_swarmagg;
using ::testing::HasSubstr;

TEST(KeysCommand, EveryKeyOfTheTableHasATypeAndAMeaning) {
  for (const swarmagg::WorldKey& key : swarmagg::world_keys()) {
    EXPECT_FALSE(key.type.empty()) << key.path;
    EXPECT_FALSE(key.meaning.empty()) << key.path << " has no meaning for the reference page";
  }
}

TEST(KeysCommand, ListsEveryKeyWithItsDefault) {
  const auto outcome = run_swarmagg("keys");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const std::string lines = "\n" + outcome.output;  // each key starts a line
  for (const std::string& path : swarmagg::world_key_paths()) {
    EXPECT_THAT(lines, HasSubstr("\n" + path + "  (")) << path;
  }
  EXPECT_THAT(outcome.output, HasSubstr("robots.count  (integer, default 150)"));
  EXPECT_THAT(outcome.output, HasSubstr("controller.stop_probability  (list of numbers, default "
                                        "[0.05, 0.2, 0.5])"));
}

TEST(KeysCommand, MarkdownHasOneTableRowPerKey) {
  const auto outcome = run_swarmagg("keys --markdown");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  for (const std::string& path : swarmagg::world_key_paths()) {
    EXPECT_THAT(outcome.output, HasSubstr("\n| `" + path + "` | ")) << path;
  }
  EXPECT_THAT(outcome.output, HasSubstr("| `arena.topology` | choice | one of: torus, walls | "
                                        "`torus` |"));
}

TEST(HelpCommand, MarkdownHoldsEveryCommandsHelp) {
  const auto outcome = run_swarmagg("help --markdown");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  for (const std::string command : {"run", "render", "model", "rates", "sweep", "merge", "plot",
                                    "reproduce", "compare", "validate", "bench", "keys"}) {
    EXPECT_THAT(outcome.output, HasSubstr("\n## " + command + "\n")) << command;
    const auto help = run_swarmagg(command + " --help");
    EXPECT_THAT(outcome.output, HasSubstr(help.output)) << command;
  }
}

}  // namespace
