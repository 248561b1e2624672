#include "view/view_command.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/errors.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

ViewCommand parse(const std::string& line) {
  ViewCommand c;
  EXPECT_TRUE(parse_view_command(line, "s.txt:1", c)) << line;
  return c;
}

std::string error_of(const std::string& line) {
  ViewCommand c;
  try {
    parse_view_command(line, "s.txt:7", c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ViewCommand, ParsesEveryScriptCommand) {
  EXPECT_EQ(parse("step 25").action, ViewAction::Step);
  EXPECT_EQ(parse("step 25").count, 25);
  EXPECT_EQ(parse("play").action, ViewAction::Play);
  EXPECT_EQ(parse("  pause  ").action, ViewAction::Pause);
  EXPECT_EQ(parse("speed 100").count, 100);
  EXPECT_EQ(parse("select 7").count, 7);
  EXPECT_EQ(parse("select none").count, -1);
  EXPECT_EQ(parse("colour aggregate").colour, ColourMode::Aggregate);
  EXPECT_EQ(parse("color size").colour, ColourMode::Size);
  EXPECT_EQ(parse("colour state").colour, ColourMode::State);
  const ViewCommand overlay = parse("overlay trails on");
  EXPECT_EQ(overlay.action, ViewAction::Overlay);
  EXPECT_EQ(overlay.overlay, Overlay::Trails);
  EXPECT_TRUE(overlay.on);
  EXPECT_FALSE(parse("overlay ghosts off").on);
  EXPECT_EQ(parse("overlay contacts on").overlay, Overlay::Contacts);
  EXPECT_FALSE(parse("panel off").on);
  EXPECT_EQ(parse("record on").action, ViewAction::Record);
  EXPECT_FALSE(parse("record off").on);
  const ViewCommand shot = parse("screenshot out/a b.png ");
  EXPECT_EQ(shot.action, ViewAction::Screenshot);
  EXPECT_EQ(shot.path, "out/a b.png");  // the rest of the line
  EXPECT_EQ(parse("hash").action, ViewAction::Hash);
  EXPECT_EQ(parse("quit  # done").action, ViewAction::Quit);
}

TEST(ViewCommand, BlankLinesAndCommentsGiveNoCommand) {
  ViewCommand c;
  EXPECT_FALSE(parse_view_command("", "s:1", c));
  EXPECT_FALSE(parse_view_command("   # a comment", "s:1", c));
}

TEST(ViewCommand, BadLinesNameTheLineAndTheExpectation) {
  EXPECT_NE(error_of("jump 3").find("s.txt:7: unknown command 'jump'"), std::string::npos);
  EXPECT_NE(error_of("step").find("expected 'step N'"), std::string::npos);
  EXPECT_NE(error_of("step 0").find("expected an integer from 1"), std::string::npos);
  EXPECT_NE(error_of("step 3x").find("got '3x'"), std::string::npos);
  EXPECT_NE(error_of("speed 20000").find("to 10000"), std::string::npos);
  EXPECT_NE(error_of("colour red").find("state, aggregate or size"), std::string::npos);
  EXPECT_NE(error_of("overlay halo on").find("detection"), std::string::npos);
  EXPECT_NE(error_of("overlay links maybe").find("expected on or off"), std::string::npos);
  EXPECT_NE(error_of("hash now").find("expected 'hash'"), std::string::npos);
}

TEST(ViewCommand, ReadsAScriptFileLineByLine) {
  const testing::ScratchDir scratch("view-script");
  const auto dir = scratch.path();
  const auto path = dir / "s.txt";
  std::ofstream(path) << "# demo\nstep 10\n\nhash\nquit\n";
  const auto commands = read_view_script(path.string());
  ASSERT_EQ(commands.size(), 3u);
  EXPECT_EQ(commands[0].count, 10);
  EXPECT_EQ(commands[2].action, ViewAction::Quit);
  std::ofstream(path) << "step 1\nstep -4\n";
  try {
    read_view_script(path.string());
    FAIL() << "a bad line must throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.txt:2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_view_script((dir / "missing.txt").string()), InputError);
  // A folder reads as nothing: it would run as an empty script.
  try {
    read_view_script(dir.string());
    FAIL() << "a folder must throw";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.string() + ": is a folder; expected a script of view commands");
  }
}

}  // namespace
}  // namespace swarmagg
