// The live view's window, run as a user would under a virtual X display (Xvfb, Mesa's
// llvmpipe): scripted and key-driven runs, checked against `swarmagg run` of the same world.
// Skipped, with a message, where xvfb-run (or xdotool) is missing; scripts/install-deps.sh
// installs both, so CI runs them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli/cli_testing.hpp"
#include "render/frame_recorder.hpp"
#include "render/render_testing.hpp"
#include "render/video.hpp"

namespace swarmagg {
namespace {

namespace fs = std::filesystem;
using testing::run_swarmagg;

const std::string kDemo = std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml";

#define SKIP_WITHOUT(program)                          \
  if (find_program(program).empty())                   \
    GTEST_SKIP() << program                            \
        " is not installed: the window tests need it " \
        "(scripts/install-deps.sh installs xvfb, xauth and xdotool)";

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

// A command line on a fresh virtual display, from the folder `cwd`. Each test is its own
// process (ctest -j): the search for a free display starts at a number of its own, so two
// tests starting at once do not race for the same one. The command's exit code is kept in a
// file: xvfb-run's own may instead report its clean-up of a display that a quickly finished
// client just left.
testing::CliOutcome on_xvfb(const std::string& command_line, const fs::path& cwd) {
  const std::string id = std::to_string(::getpid());
  const fs::path script = fs::temp_directory_path() / ("swarmagg-view-command-" + id + ".sh");
  const fs::path status_file = fs::temp_directory_path() / ("swarmagg-view-status-" + id);
  fs::remove(status_file);
  write_text(script, command_line + "\necho $? > '" + status_file.string() + "'\n");
  const std::string first_display = std::to_string(100 + ::getpid() % 800);
  const std::string command = "cd '" + cwd.string() + "' && xvfb-run -a -n " + first_display +
                              " -s '-screen 0 1024x768x24' sh '" + script.string() + "'";
  testing::CliOutcome outcome;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return outcome;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) outcome.output += buffer;
  const int status = pclose(pipe);
  std::ifstream kept(status_file);
  if (!(kept >> outcome.exit_code))
    outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  fs::remove(script);
  fs::remove(status_file);
  return outcome;
}

testing::CliOutcome run_on_xvfb(const std::string& arguments, const fs::path& cwd) {
  return on_xvfb(std::string(SWARMAGG_BINARY) + " " + arguments, cwd);
}

// The demo's view at 320x240 on a virtual display, driven through the X server: `window`
// (shell lines given the window id in $wid, run before it is focused), then `keys`, then Q.
testing::CliOutcome drive_view(const fs::path& dir, const std::string& window,
                               const std::string& keys) {
  write_text(dir / "drive.sh",
             "set -e\n" + std::string(SWARMAGG_BINARY) + " view " + kDemo +
                 " --size 320x240 &\n"
                 "pid=$!\n"
                 "wid=$(xdotool search --sync --name 'swarmagg view' | head -1)\n" +
                 window +
                 "xdotool windowfocus --sync $wid\n"
                 "sleep 0.5\n" +
                 keys +
                 "sleep 0.5\n"
                 "xdotool key q\n"
                 "wait $pid\n");
  return on_xvfb("sh drive.sh", dir);
}

// The frame `run --render-every steps` draws after `steps` steps, at width x height.
testing::Image run_frame(const fs::path& dir, const std::string& engine, std::int64_t steps,
                         const std::string& size) {
  const fs::path out = dir / ("run-" + engine + "-" + std::to_string(steps));
  const auto outcome = run_swarmagg("run " + kDemo + " --engine " + engine +
                                    " --set run.duration=" + std::to_string(steps * 0.1) +
                                    " --set run.replicates=1 --render-every " +
                                    std::to_string(steps) + " --render-size " + size + " --out " +
                                    out.string() + " --quiet --no-plots --no-model");
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
  return testing::read_png(out / "frames" / "frame_000001.png");
}

std::size_t pixels_differing(const testing::Image& a, const testing::Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 3 < std::min(a.rgba.size(), b.rgba.size()); i += 4) {
    if (a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2])
      ++differing;
  }
  return differing;
}

class ViewWindowEngines : public ::testing::TestWithParam<std::string> {};

TEST_P(ViewWindowEngines, ScriptedHashIsTheRunsFinalStateHash) {
  SKIP_WITHOUT("xvfb-run");
  const testing::ScratchDir dir("view-hash-" + GetParam());
  const auto run = run_swarmagg("run " + kDemo + " --engine " + GetParam() +
                                " --set run.duration=4 --set run.replicates=2 --out " +
                                (dir.path() / "run").string() + " --quiet --no-plots --no-model");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary =
      nlohmann::json::parse(testing::read_all(dir.path() / "run" / "summary.json"));
  const std::string expected = summary["replicates"][1]["final_state_hash"];

  write_text(dir.path() / "s.txt", "step 15\nstep 25\nhash\nquit\n");
  const auto view = run_on_xvfb("view " + kDemo + " --engine " + GetParam() +
                                    " --replicate 1 --set run.replicates=2 --size 200x200 "
                                    "--script s.txt",
                                dir.path());
  ASSERT_EQ(view.exit_code, 0) << view.output;
  EXPECT_NE(view.output.find("state-hash " + expected + " step 40\n"), std::string::npos)
      << view.output << " expected " << expected;
}

INSTANTIATE_TEST_SUITE_P(BothEngines, ViewWindowEngines, ::testing::Values("kinematic", "box2d"));

// The window shows the off-screen renderer's frame 1:1: with the panel off, a screenshot is
// the frame `run --render-every` writes, pixel for pixel (no tolerance).
TEST(ViewWindow, ScreenshotWithThePanelOffIsTheRunsFrame) {
  SKIP_WITHOUT("xvfb-run");
  const testing::ScratchDir dir("view-shot");
  write_text(dir.path() / "s.txt",
             "step 30\nscreenshot with panel.png\npanel off\nscreenshot plain.png\n"
             "colour aggregate\nscreenshot aggregate.png\nquit\n");
  const auto view = run_on_xvfb("view " + kDemo + " --size 320x240 --script s.txt", dir.path());
  ASSERT_EQ(view.exit_code, 0) << view.output;
  const testing::Image frame = run_frame(dir.path(), "kinematic", 30, "320x240");
  const testing::Image plain = testing::read_png(dir.path() / "plain.png");
  EXPECT_EQ(pixels_differing(plain, frame), 0u);
  // The panel and the colour mode do show: those screenshots are not the frame.
  EXPECT_GT(pixels_differing(testing::read_png(dir.path() / "with panel.png"), frame), 1000u);
  EXPECT_GT(pixels_differing(testing::read_png(dir.path() / "aggregate.png"), frame), 10u);
}

// Recording writes the frames `run --render-every` would at the same steps, into a folder
// that `swarmagg video` turns into a video.
TEST(ViewWindow, RecordsAFrameEveryKSteps) {
  SKIP_WITHOUT("xvfb-run");
  const testing::ScratchDir dir("view-record");
  // Quit while recording: the recording ends as `record off` would end it, saying so.
  write_text(dir.path() / "s.txt", "step 5\nrecord on\nstep 25\nquit\n");
  const auto view = run_on_xvfb(
      "view " + kDemo + " --set render.every=10 --size 200x160 --script s.txt", dir.path());
  ASSERT_EQ(view.exit_code, 0) << view.output;
  EXPECT_NE(view.output.find("recorded 3 frames into renders/demo-view/"), std::string::npos)
      << view.output;
  const fs::path frames = dir.path() / "renders" / "demo-view";
  // Steps 10, 20 and 30 (recording starts at step 5, which is no multiple of 10).
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(fs::exists(frames / FrameRecorder::frame_name(i))) << i;
  EXPECT_FALSE(fs::exists(frames / FrameRecorder::frame_name(3)));
  const testing::Image frame = run_frame(dir.path(), "kinematic", 30, "200x160");
  EXPECT_EQ(pixels_differing(testing::read_png(frames / FrameRecorder::frame_name(2)), frame), 0u);
  if (!find_program("ffmpeg").empty()) {
    const auto video =
        run_swarmagg("video " + frames.string() + " " + (dir.path() / "v.mp4").string());
    EXPECT_EQ(video.exit_code, 0) << video.output;
    EXPECT_GT(fs::file_size(dir.path() / "v.mp4"), 0u);
  }
}

TEST(ViewWindow, WithoutADisplayExitsAtOnceSayingHowToRunIt) {
  const auto outcome = run_swarmagg("view " + kDemo, "env -u DISPLAY");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.output.find("xvfb-run"), std::string::npos) << outcome.output;
  const auto bad = run_swarmagg("view " + kDemo, "DISPLAY=:987654");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("cannot open the display"), std::string::npos) << bad.output;
}

TEST(ViewWindow, BadScriptIsBadInput) {
  const testing::ScratchDir dir("view-bad-script");
  write_text(dir.path() / "s.txt", "step 3\nfly away\n");
  const auto outcome =
      run_swarmagg("view " + kDemo + " --script " + (dir.path() / "s.txt").string(), "DISPLAY=:0");
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.output.find("s.txt:2: unknown command 'fly'"), std::string::npos)
      << outcome.output;
}

// A scripted command that fails while the view runs ends it as an error naming its line (it
// printed the failure and exited 0); a typed one only shows its message.
TEST(ViewWindow, AScriptedCommandThatFailsEndsTheViewNamingItsLine) {
  SKIP_WITHOUT("xvfb-run");
  const testing::ScratchDir dir("view-failing-script");
  const auto view_exit_code = [&](const std::string& script, std::string& output) {
    const auto outcome = run_on_xvfb("view " + kDemo + " --script " + script, dir.path());
    output = outcome.output;
    return outcome.exit_code;
  };
  std::string output;
  write_text(dir.path() / "select.txt", "step 2\nselect 60\nquit\n");
  EXPECT_EQ(view_exit_code("select.txt", output), 2) << output;
  EXPECT_NE(output.find("select.txt:2: select 60: the world has agents 0 to 59"), std::string::npos)
      << output;
  fs::create_directories(dir.path() / "a-folder");
  write_text(dir.path() / "shot.txt", "screenshot a-folder\nquit\n");
  EXPECT_EQ(view_exit_code("shot.txt", output), 1) << output;
  EXPECT_NE(output.find("shot.txt:1: screenshot failed"), std::string::npos) << output;
}

// Real key presses through the X server (xdotool): play and pause (Space twice), three single
// steps (.), hide the panel (Tab), screenshot (S), quit (Q). The screenshot is named after the
// step it shows, and must be the run's frame of that step: had the view not paused, it would
// show a later step.
TEST(ViewWindow, KeysPauseStepAndTakeAScreenshot) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const testing::ScratchDir dir("view-keys");
  const auto outcome = drive_view(dir.path(), "",
                                  "xdotool key --delay 150 space\n"
                                  "sleep 1\n"
                                  "xdotool key --delay 150 space period period period Tab s\n");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  fs::path shot;
  std::int64_t step = -1;
  const std::regex name("demo-step([0-9]+)\\.png");
  for (const auto& entry : fs::directory_iterator(dir.path())) {
    std::smatch m;
    const std::string file = entry.path().filename().string();
    if (std::regex_match(file, m, name)) {
      shot = entry.path();
      step = std::stoll(m[1]);
    }
  }
  ASSERT_FALSE(shot.empty()) << "no screenshot appeared; output: " << outcome.output;
  // Three single steps after however many it played (none if a loaded machine handled both
  // Space presses in one frame).
  EXPECT_GE(step, 3);
  const testing::Image frame = run_frame(dir.path(), "kinematic", step, "320x240");
  EXPECT_EQ(pixels_differing(testing::read_png(shot), frame), 0u) << shot;
}

// S twice at one step (a zoom or a reset in between) keeps both screenshots.
TEST(ViewWindow, ASecondScreenshotOfAStepKeepsTheFirst) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const testing::ScratchDir dir("view-two-shots");
  const auto outcome = drive_view(dir.path(), "", "xdotool key --delay 300 s s\n");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_TRUE(fs::exists(dir.path() / "demo-step0.png")) << outcome.output;
  EXPECT_TRUE(fs::exists(dir.path() / "demo-step0-2.png")) << outcome.output;
}

// A window resized anyway (xdotool here, a tiling window manager elsewhere) still shows and
// screenshots the frame at its own size: the screenshot came out shifted, part blank.
TEST(ViewWindow, AResizedWindowStillScreenshotsTheFrame) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const testing::ScratchDir dir("view-resized");
  const auto outcome = drive_view(dir.path(), "xdotool windowsize --sync $wid 400 180\n",
                                  "xdotool key --delay 150 period Tab s\n");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const fs::path shot = dir.path() / "demo-step1.png";
  ASSERT_TRUE(fs::exists(shot)) << outcome.output;
  const testing::Image frame = run_frame(dir.path(), "kinematic", 1, "320x240");
  EXPECT_EQ(pixels_differing(testing::read_png(shot), frame), 0u) << shot;
}

}  // namespace
}  // namespace swarmagg
