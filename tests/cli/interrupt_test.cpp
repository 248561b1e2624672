// SIGINT or SIGTERM during `swarmagg run` or `sweep`: the run stops, exits 130 (143), keeps
// every completed output intact and leaves no partial file behind. The binary runs a world
// long enough to be caught mid-run; the signal is sent once its handlers are installed.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/cli_testing.hpp"
#include "render/video.hpp"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using Clock = std::chrono::steady_clock;
using swarmagg::testing::read_all;

const std::string kLongWorld = std::string(SWARMAGG_SOURCE_DIR) + "/worlds/paper/full-0.0025.yaml";

struct Outcome {
  int exit_code = -1;  // -1 unless the process exited normally
  int signal_number = 0;
  bool timed_out = false;
  std::string output;  // stdout and stderr together
};

// A running `swarmagg`, its stdout and stderr going to one pipe.
class Child {
 public:
  // `own_group`: the child leads a process group of its own, as a shell's job does, so that
  // send_to_group reaches the programs it starts (ffmpeg) as Ctrl-C in a terminal would.
  explicit Child(const std::vector<std::string>& arguments, bool own_group = false) {
    int fds[2];
    if (pipe(fds) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    std::vector<char*> argv;
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    if (own_group) {
      posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
      posix_spawnattr_setpgroup(&attributes, 0);
    }
    if (posix_spawn(&pid_, argv[0], &actions, &attributes, argv.data(), environ) != 0) pid_ = -1;
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    reader_ = fds[0];
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    if (pid_ > 0 && !reaped_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
    if (reader_ >= 0) close(reader_);
  }

  bool started() const { return pid_ > 0; }

  // The signal handlers are in place once /proc shows SIGINT and SIGTERM as caught; a signal
  // sent earlier would kill the process the default way.
  bool wait_for_handlers(std::chrono::seconds limit) const {
    const unsigned long wanted = (1ul << (SIGINT - 1)) | (1ul << (SIGTERM - 1));
    for (const auto deadline = Clock::now() + limit; Clock::now() < deadline;) {
      std::ifstream status("/proc/" + std::to_string(pid_) + "/status");
      for (std::string line; std::getline(status, line);) {
        if (line.rfind("SigCgt:", 0) != 0) continue;
        if ((std::stoul(line.substr(7), nullptr, 16) & wanted) == wanted) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }

  void send(int signal_number) const { kill(pid_, signal_number); }
  void send_to_group(int signal_number) const { kill(-pid_, signal_number); }

  // Reads the output until it holds `text` (kept for wait()); false at the limit or the end.
  bool wait_for_text(const std::string& text, std::chrono::seconds limit) {
    const auto deadline = Clock::now() + limit;
    pollfd pipe_end{reader_, POLLIN, 0};
    char buffer[4096];
    while (early_output_.find(text) == std::string::npos) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) return false;
      if (poll(&pipe_end, 1, static_cast<int>(left.count())) <= 0) continue;
      const ssize_t got = read(reader_, buffer, sizeof buffer);
      if (got <= 0) return false;
      early_output_.append(buffer, static_cast<std::size_t>(got));
    }
    return true;
  }

  Outcome wait(std::chrono::seconds limit) {
    Outcome outcome;
    outcome.output = early_output_;
    const auto deadline = Clock::now() + limit;
    pollfd pipe_end{reader_, POLLIN, 0};
    char buffer[4096];
    while (true) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
      if (left.count() <= 0) {
        outcome.timed_out = true;
        kill(pid_, SIGKILL);
        break;
      }
      if (poll(&pipe_end, 1, static_cast<int>(left.count())) <= 0) continue;
      const ssize_t got = read(reader_, buffer, sizeof buffer);
      if (got <= 0) break;
      outcome.output.append(buffer, static_cast<std::size_t>(got));
    }
    int status = 0;
    waitpid(pid_, &status, 0);
    reaped_ = true;
    if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal_number = WTERMSIG(status);
    return outcome;
  }

 private:
  pid_t pid_ = -1;
  int reader_ = -1;
  bool reaped_ = false;
  std::string early_output_;  // read by wait_for_text
};

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("swarmagg-interrupt-" + name);
  fs::remove_all(dir);
  return dir;
}

// Every file below `dir` (relative path -> content).
std::map<std::string, std::string> files_below(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), dir).string()] = read_all(entry.path());
  }
  return files;
}

std::vector<std::string> temporary_files_below(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& [name, content] : files_below(dir)) {
    if (name.ends_with(".tmp")) found.push_back(name);
  }
  return found;
}

// Starts `arguments`, interrupts it with `signal_number` `delay` after its handlers are in
// place and waits for it to stop.
Outcome interrupt(const std::vector<std::string>& arguments, int signal_number,
                  std::chrono::milliseconds delay) {
  Child child(arguments);
  EXPECT_TRUE(child.started());
  EXPECT_TRUE(child.wait_for_handlers(std::chrono::seconds(60))) << "never installed its handlers";
  std::this_thread::sleep_for(delay);
  child.send(signal_number);
  return child.wait(std::chrono::seconds(60));
}

std::vector<std::string> long_run(const fs::path& out) {
  // 10^7 steps of 120 agents in each of two replicates: far longer than the test waits.
  // --force: it replaces the earlier run some tests leave in `out`.
  return {SWARMAGG_BINARY, "run",   kLongWorld,  "--replicates",         "2",
          "--threads",     "2",     "--set",     "run.duration=1000000", "--quiet",
          "--force",       "--out", out.string()};
}

void expect_interrupted(const Outcome& o, int code) {
  ASSERT_FALSE(o.timed_out) << "did not stop within a minute of the signal";
  ASSERT_EQ(o.signal_number, 0) << "killed by signal " << o.signal_number << ":\n" << o.output;
  EXPECT_EQ(o.exit_code, code) << o.output;
  EXPECT_THAT(o.output, HasSubstr("interrupted; completed outputs are intact"));
}

// A complete run of the same world in `out`, as a user's earlier run would have left it.
std::map<std::string, std::string> earlier_run(const fs::path& out) {
  Child child({SWARMAGG_BINARY, "run", kLongWorld, "--replicates", "1", "--set", "run.duration=20",
               "--quiet", "--out", out.string()});
  const Outcome o = child.wait(std::chrono::seconds(120));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  return files_below(out);
}

TEST(Interrupt, SigintStopsARunWithExitCode130AndKeepsTheEarlierOutputIntact) {
  const fs::path out = fresh_dir("sigint");
  const auto before = earlier_run(out);
  ASSERT_TRUE(before.contains("world.resolved.yaml"));
  ASSERT_TRUE(before.contains("timeseries.csv"));
  expect_interrupted(interrupt(long_run(out), SIGINT, std::chrono::milliseconds(500)), 130);
  EXPECT_EQ(files_below(out), before) << "the earlier complete output changed";
  fs::remove_all(out);
}

TEST(Interrupt, SigtermStopsARunWithExitCode143AndLeavesNoPartialFile) {
  const fs::path out = fresh_dir("sigterm");
  expect_interrupted(interrupt(long_run(out), SIGTERM, std::chrono::milliseconds(500)), 143);
  EXPECT_THAT(temporary_files_below(out), ::testing::IsEmpty());
  // world.resolved.yaml is written last: without it, no other output may exist either.
  const auto after = files_below(out);
  if (!after.contains("world.resolved.yaml")) {
    EXPECT_TRUE(after.empty()) << after.size() << " outputs of an incomplete run";
    EXPECT_FALSE(fs::exists(out)) << "the folder made for an interrupted run stayed";
  }
  fs::remove_all(out);
}

// A first run drawing frames, stopped: neither its folder nor an empty frame folder stays to
// make the same command refuse an "earlier run" next time.
TEST(Interrupt, AStoppedFirstRunDrawingFramesLeavesNoFolder) {
  const fs::path out = fresh_dir("first-frames");
  auto arguments = long_run(out);
  for (const char* extra : {"--render-every", "100", "--render-size", "64x64"})
    arguments.push_back(extra);
  expect_interrupted(interrupt(arguments, SIGINT, std::chrono::milliseconds(500)), 130);
  EXPECT_FALSE(fs::exists(out)) << "left " << (fs::exists(out / "frames") ? "frames/" : "a folder");
  fs::remove_all(out);
}

TEST(Interrupt, ARunStoringTrajectoriesLeavesNoHalfWrittenH5) {
  const fs::path out = fresh_dir("trajectories");
  auto arguments = long_run(out);
  arguments.insert(arguments.end(), {"--trajectories", "100"});
  expect_interrupted(interrupt(arguments, SIGTERM, std::chrono::milliseconds(1500)), 143);
  EXPECT_FALSE(fs::exists(out / "trajectories.h5"));
  EXPECT_THAT(temporary_files_below(out), ::testing::IsEmpty());
  // The folder was made for this run's files (its trajectories and timeseries while it ran).
  EXPECT_FALSE(fs::exists(out)) << "the folder made for an interrupted run stayed";
  fs::remove_all(out);
}

// Polls `ready` every 5 ms for up to a minute; whether it became true.
bool wait_until(const std::function<bool()>& ready) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!ready() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  return ready();
}

// Files below `dir` whose names are `counted`, counted while a child may be writing there: a folder
// that vanishes mid-count ends the count instead of throwing.
int count_below(const fs::path& dir, const std::function<bool(const std::string&)>& counted) {
  int count = 0;
  std::error_code gone;
  fs::recursive_directory_iterator entry(dir, gone);
  for (; !gone && entry != fs::recursive_directory_iterator(); entry.increment(gone))
    count += counted(entry->path().filename().string()) ? 1 : 0;
  return count;
}

// Whether `dir` itself (not below) holds a file whose name is `wanted`, read while a child
// may be changing it.
bool holds_file(const fs::path& dir, const std::function<bool(const std::string&)>& wanted) {
  std::error_code gone;
  for (const auto& entry : fs::directory_iterator(dir, gone)) {
    if (wanted(entry.path().filename().string())) return true;
  }
  return false;
}

int count_named_below(const fs::path& dir, const std::string& name) {
  return count_below(dir, [&](const std::string& file) { return file == name; });
}

// A run killed outright (SIGKILL, out of memory) leaves its rows' temporaries in the folder
// made for it; they are a dead process's garbage, so the same command runs again there
// without --force.
TEST(Interrupt, ARunKilledOutrightDoesNotBlockTheSameRunAgain) {
  const fs::path out = fresh_dir("killed");
  Child child({SWARMAGG_BINARY, "run", kLongWorld, "--replicates", "1", "--set",
               "run.duration=1000000", "--quiet", "--out", out.string()});
  ASSERT_TRUE(child.wait_for_handlers(std::chrono::seconds(60)));
  const auto spooling = [&] {
    return count_below(out, [](const std::string& file) { return file.ends_with(".tmp"); }) > 0;
  };
  ASSERT_TRUE(wait_until(spooling)) << "no rows spooled";
  child.send(SIGKILL);
  ASSERT_EQ(child.wait(std::chrono::seconds(60)).signal_number, SIGKILL);
  Child again({SWARMAGG_BINARY, "run", kLongWorld, "--replicates", "1", "--set", "run.duration=20",
               "--quiet", "--no-plots", "--no-model", "--out", out.string()});
  const Outcome o = again.wait(std::chrono::seconds(120));
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(temporary_files_below(out), ::testing::IsEmpty());
  EXPECT_TRUE(fs::exists(out / "world.resolved.yaml"));
  fs::remove_all(out);
}

TEST(Interrupt, ASignalAtOnceStillExitsCleanly) {
  const fs::path out = fresh_dir("at-once");
  expect_interrupted(interrupt(long_run(out), SIGINT, std::chrono::milliseconds(0)), 130);
  EXPECT_FALSE(fs::exists(out / "timeseries.csv"));
  fs::remove_all(out);
}

// Starts `arguments`, waits until its frames are staged (`frame` drawn in a hidden staging
// folder in `frames`), then sends SIGINT and expects it to stop as interrupted.
void interrupt_once_staged(const std::vector<std::string>& arguments, const fs::path& frames,
                           const std::string& frame) {
  Child child(arguments);
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for_handlers(std::chrono::seconds(60)));
  const auto staged = [&] {
    std::error_code gone;  // the directory may change while it is read
    for (const auto& entry : fs::directory_iterator(frames, gone)) {
      if (entry.path().filename().string().starts_with(".staged-frames.") &&
          fs::exists(entry.path() / frame, gone))
        return true;
    }
    return false;
  };
  EXPECT_TRUE(wait_until(staged)) << "no frame was staged in a minute: the staging went untested";
  child.send(SIGINT);
  expect_interrupted(child.wait(std::chrono::seconds(60)), 130);
}

// Drawing a frame every step, a run stops at the step the signal came in, not at the next
// multiple of 1024 steps (it drew on for seconds, to frame 1025).
// The frames an earlier run drew stay whole until the new simulation has finished, as its
// other outputs do: the new frames are drawn aside (render/staged_frames.hpp), and Ctrl-C
// leaves neither them nor a half-replaced frame folder.
TEST(Interrupt, ARunDrawingFramesStopsAtTheNextStepAndKeepsTheEarlierFrames) {
  const fs::path out = fresh_dir("frames");
  const std::vector<std::string> render = {"--render-every", "1", "--render-size", "64x64"};
  std::vector<std::string> earlier = {
      SWARMAGG_BINARY,  "run",     kLongWorld, "--replicates", "1", "--set",
      "run.duration=1", "--quiet", "--out",    out.string()};
  earlier.insert(earlier.end(), render.begin(), render.end());
  ASSERT_EQ(Child(earlier).wait(std::chrono::seconds(120)).exit_code, 0);
  const auto before = files_below(out / "frames");
  ASSERT_EQ(before.size(), 11u);  // steps 0..10
  std::vector<std::string> longer = {
      SWARMAGG_BINARY,    "run",     kLongWorld, "--replicates", "1", "--set",
      "run.duration=300", "--force", "--out",    out.string()};
  longer.insert(longer.end(), render.begin(), render.end());
  interrupt_once_staged(longer, out / "frames", "frame_000020.png");
  EXPECT_EQ(files_below(out / "frames"), before);  // the staged frames went too
  fs::remove_all(out);
}

// `render` draws into the run's own frames/ by default: stopped part way, it leaves the
// frames the run drew there as they were (it removed them, and left its partial ones).
TEST(Interrupt, AStoppedRenderKeepsTheFramesAlreadyThere) {
  const fs::path out = fresh_dir("render");
  ASSERT_EQ(Child({SWARMAGG_BINARY, "run", kLongWorld, "--replicates", "1", "--set",
                   "run.duration=30", "--trajectories", "1", "--render-every", "10",
                   "--render-size", "64x64", "--quiet", "--no-plots", "--out", out.string()})
                .wait(std::chrono::seconds(120))
                .exit_code,
            0);
  const auto before = files_below(out / "frames");
  ASSERT_EQ(before.size(), 31u);  // steps 0, 10, ..., 300
  interrupt_once_staged(
      {SWARMAGG_BINARY, "render", out.string(), "--every", "1", "--size", "1200x1200"},
      out / "frames", "frame_000002.png");
  EXPECT_EQ(files_below(out / "frames"), before);
  fs::remove_all(out);
}

// Ctrl-C in a terminal reaches `video` and its ffmpeg alike: the half-made video goes, and the
// command exits as interrupted (the hidden temporary stayed before).
TEST(Interrupt, SigintStopsAVideoAndLeavesNoHalfMadeFile) {
  if (swarmagg::find_program("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path out = fresh_dir("video");
  ASSERT_EQ(system((std::string(SWARMAGG_BINARY) + " run " + kLongWorld +
                    " --replicates 1 --set run.duration=200 --render-every 1 --render-size "
                    "256x256 --no-plots --no-model --quiet --out " +
                    out.string() + " >/dev/null")
                       .c_str()),
            0);
  Child child({SWARMAGG_BINARY, "video", (out / "frames").string(), (out / "v.mp4").string()},
              true);
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for_handlers(std::chrono::seconds(60)));
  // Once the video's hidden temporary exists the real ffmpeg is under way, past the probe
  // that checks what it can make (SigintDuringTheVideoProbeExitsAsInterrupted).
  const auto writing = [&] {
    return holds_file(out, [](const std::string& file) { return file.ends_with(".tmp.mp4"); });
  };
  ASSERT_TRUE(wait_until(writing)) << "ffmpeg never started the video";
  child.send_to_group(SIGINT);
  const Outcome o = child.wait(std::chrono::seconds(60));
  if (o.exit_code == 0) GTEST_SKIP() << "ffmpeg finished before the signal";
  expect_interrupted(o, 130);
  EXPECT_FALSE(fs::exists(out / "v.mp4"));
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "left " << entry.path();
  fs::remove_all(out);
}

// Before the video, ffmpeg makes a two-frame probe to check it can write that kind of file.
// Ctrl-C during the probe kills it too, and the command exits as interrupted, not as bad input
// (exit 2: "ffmpeg cannot make a .mp4 video"). A stand-in ffmpeg that waits for the signal
// makes the timing certain.
TEST(Interrupt, SigintDuringTheVideoProbeExitsAsInterrupted) {
  const fs::path dir = fresh_dir("video-probe");
  fs::create_directories(dir / "frames");
  fs::create_directories(dir / "bin");
  std::ofstream(dir / "frames" / "frame_000000.png") << "not read before the probe";
  const fs::path started = dir / "ffmpeg-started";
  std::ofstream(dir / "bin" / "ffmpeg")
      << "#!/bin/sh\n: > '" << started.string() << "'\nexec sleep 60\n";
  fs::permissions(dir / "bin" / "ffmpeg", fs::perms::owner_all);
  const std::string path = std::getenv("PATH");
  setenv("PATH", ((dir / "bin").string() + ":" + path).c_str(), 1);
  Child child({SWARMAGG_BINARY, "video", (dir / "frames").string(), (dir / "v.mp4").string()},
              true);
  setenv("PATH", path.c_str(), 1);
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for_handlers(std::chrono::seconds(60)));
  ASSERT_TRUE(wait_until([&] { return fs::exists(started); })) << "the probe never started";
  child.send_to_group(SIGINT);
  expect_interrupted(child.wait(std::chrono::seconds(60)), 130);
  EXPECT_FALSE(fs::exists(dir / "v.mp4"));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "left " << entry.path();
  fs::remove_all(dir);
}

// Ctrl-C after the simulation, while the models are computed: no later phase starts, the run
// exits as interrupted, not as a success, and says how to add the model to the kept run.
TEST(Interrupt, ASignalAfterTheSimulationStopsBeforeThePlotsWithExitCode130) {
  const fs::path out = fresh_dir("model-phase");
  Child child({SWARMAGG_BINARY, "run", kLongWorld, "--replicates", "1", "--set",
               "run.duration=5000", "--set", "model.stochastic_replicates=200", "--progress",
               "always", "--out", out.string()});
  ASSERT_TRUE(child.started());
  ASSERT_TRUE(child.wait_for_text("computing the model predictions", std::chrono::seconds(60)));
  child.send(SIGINT);
  const Outcome o = child.wait(std::chrono::seconds(120));
  expect_interrupted(o, 130);
  EXPECT_THAT(o.output, ::testing::Not(HasSubstr("drawing the plots")));
  EXPECT_TRUE(fs::exists(out / "world.resolved.yaml")) << "the simulation's outputs stay";
  EXPECT_THAT(o.output,
              HasSubstr("are complete; what follows them is not. To add it: swarmagg "
                        "model " +
                        out.string() + "/world.resolved.yaml --out " + out.string() + "\n"));
  EXPECT_THAT(temporary_files_below(out), ::testing::IsEmpty());
  fs::remove_all(out);
}

// `swarmagg model` of a long run (gigabytes of rows, written while they are computed) stops at
// Ctrl-C: the folder keeps the model outputs it had, and no temporary remains.
TEST(Interrupt, SigintStopsALongModelAndKeepsTheEarlierModelOutputs) {
  const fs::path out = fresh_dir("model");
  Child earlier({SWARMAGG_BINARY, "model", kLongWorld, "--set", "run.duration=20", "--quiet",
                 "--out", out.string()});
  ASSERT_EQ(earlier.wait(std::chrono::seconds(120)).exit_code, 0);
  const auto before = files_below(out);
  ASSERT_TRUE(before.contains("model.csv"));
  Child child({SWARMAGG_BINARY, "model", kLongWorld, "--set", "run.duration=1000000", "--quiet",
               "--out", out.string()});
  ASSERT_TRUE(child.wait_for_handlers(std::chrono::seconds(60)));
  // Once it writes its model.csv temporary it is in the walks, past the placements.
  const auto writing = [&] {
    return holds_file(out, [](const std::string& file) { return file.starts_with(".model.csv."); });
  };
  ASSERT_TRUE(wait_until(writing)) << "never started writing its model";
  child.send(SIGINT);
  expect_interrupted(child.wait(std::chrono::seconds(60)), 130);
  EXPECT_EQ(files_below(out), before) << "the earlier model outputs changed";
  fs::remove_all(out);
}

// `compare` spools its arms' rows into its folder while they run: interrupted, it removes
// them, keeps an earlier comparison there whole, and leaves no folder made for it.
TEST(Interrupt, SigintStopsACompareAndKeepsTheEarlierComparison) {
  const fs::path out = fresh_dir("compare");
  auto compare = [&out](const std::string& duration) {
    return std::vector<std::string>{SWARMAGG_BINARY,
                                    "compare",
                                    kLongWorld,
                                    "--replicates",
                                    "2",
                                    "--set",
                                    "run.duration=" + duration,
                                    "--quiet",
                                    "--force",
                                    "--out",
                                    out.string()};
  };
  expect_interrupted(interrupt(compare("1000000"), SIGTERM, std::chrono::milliseconds(500)), 143);
  EXPECT_FALSE(fs::exists(out)) << "the folder made for an interrupted comparison stayed";
  Child earlier(compare("20"));
  ASSERT_EQ(earlier.wait(std::chrono::seconds(120)).exit_code, 0);
  const auto before = files_below(out);
  ASSERT_TRUE(before.contains("kinematic/timeseries.csv"));
  expect_interrupted(interrupt(compare("1000000"), SIGINT, std::chrono::milliseconds(500)), 130);
  EXPECT_EQ(files_below(out), before) << "the earlier comparison changed";
  fs::remove_all(out);
}

// A sweep of three runs, two short and one long: interrupted during the long one, the short
// ones stay complete and the long one leaves no folder.
TEST(Interrupt, SigintStopsASweepAndKeepsItsCompletedRuns) {
  const fs::path dir = fresh_dir("sweep");
  fs::create_directories(dir);
  const fs::path sweep = dir / "sweep.yaml";
  std::ofstream(sweep) << "name: interrupted\nbase: " << kLongWorld
                       << "\nparameters:\n  run.duration: [20, 30, 1000000]\nreplicates: 1\n"
                          "seed: 1\n";
  const fs::path out = dir / "out";
  Child child({SWARMAGG_BINARY, "sweep", sweep.string(), "--threads", "1", "--quiet", "--no-plots",
               "--out", out.string()});
  ASSERT_TRUE(child.wait_for_handlers(std::chrono::seconds(60)));
  // A fixed delay could end before the short runs' last writes on a slow disk.
  ASSERT_TRUE(wait_until([&] { return count_named_below(out, "world.resolved.yaml") == 2; }))
      << "the two short runs did not complete in a minute";
  child.send(SIGINT);
  expect_interrupted(child.wait(std::chrono::seconds(60)), 130);
  EXPECT_THAT(temporary_files_below(out), ::testing::IsEmpty());
  int complete = 0;
  for (const auto& point : fs::directory_iterator(out / "runs")) {
    for (const auto& run : fs::directory_iterator(point.path())) {
      EXPECT_TRUE(fs::exists(run.path() / "world.resolved.yaml")) << run.path() << " is partial";
      EXPECT_TRUE(fs::exists(run.path() / "timeseries.csv")) << run.path();
      ++complete;
    }
  }
  EXPECT_EQ(complete, 2) << "the two short runs complete, the long one absent";
  fs::remove_all(dir);
}

// Two replicates of one point side by side share the point's folder; stopped, neither leaves
// it (or runs/) behind empty.
TEST(Interrupt, ASweepStoppedOnTwoThreadsLeavesNoEmptyFolder) {
  const fs::path dir = fresh_dir("sweep-two-threads");
  fs::create_directories(dir);
  const fs::path sweep = dir / "sweep.yaml";
  std::ofstream(sweep) << "name: side-by-side\nbase: " << kLongWorld
                       << "\nparameters:\n  run.duration: [1000000]\nreplicates: 2\nseed: 1\n";
  const fs::path out = dir / "out";
  expect_interrupted(interrupt({SWARMAGG_BINARY, "sweep", sweep.string(), "--threads", "2",
                                "--quiet", "--no-plots", "--out", out.string()},
                               SIGINT, std::chrono::milliseconds(1000)),
                     130);
  EXPECT_FALSE(fs::exists(out / "runs")) << "the stopped runs left folders";
  EXPECT_TRUE(fs::exists(out / "sweep.json")) << "the manifest, to resume from, stays";
  fs::remove_all(dir);
}

}  // namespace
