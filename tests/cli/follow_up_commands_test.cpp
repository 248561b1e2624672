// The commands messages print for the user to paste: each path one shell word, and the model
// preceded by the rates it needs.
#include "cli/follow_up_commands.hpp"

#include <gtest/gtest.h>

namespace swarmagg::cli {
namespace {

TEST(ShellWord, PlainPathsStayAndOthersAreQuoted) {
  EXPECT_EQ(shell_word("runs/demo-1.5"), "runs/demo-1.5");
  EXPECT_EQ(shell_word("my runs/x"), "'my runs/x'");
  EXPECT_EQ(shell_word("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_word(""), "''");
  EXPECT_EQ(shell_word("-x/run"), "./-x/run");  // not read as an option
  EXPECT_EQ(shell_word("r\xc3\xa9sultats"), "'r\xc3\xa9sultats'");
}

TEST(RatesAndModelCommands, TheModelNeedsTheRatesFirstWhenThereAreNone) {
  EXPECT_EQ(rates_and_model_commands("/nonexistent/r", false),
            "swarmagg model /nonexistent/r/world.resolved.yaml --out /nonexistent/r");
  EXPECT_EQ(rates_and_model_commands("/nonexistent/r", true),
            "swarmagg rates /nonexistent/r/world.resolved.yaml --out /nonexistent/r && "
            "swarmagg model /nonexistent/r/world.resolved.yaml --rates /nonexistent/r/rates.csv "
            "--out /nonexistent/r");
  EXPECT_EQ(rates_and_model_commands("/nonexistent/r", true, false),
            "swarmagg rates /nonexistent/r/world.resolved.yaml --out /nonexistent/r");
  EXPECT_EQ(rates_and_model_commands("/nonexistent/a b", false),
            "swarmagg model '/nonexistent/a b/world.resolved.yaml' --out '/nonexistent/a b'");
}

}  // namespace
}  // namespace swarmagg::cli
