// The `sweep` and `merge` commands end to end, through the built executable: exit codes,
// messages, and a sweep killed in the middle (SIGINT, SIGTERM, SIGKILL) then resumed.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

#include "sweep_testing.hpp"

extern char** environ;

namespace swarmagg {
namespace {

using ::testing::HasSubstr;
using testing::read_file_text;

// 2 x 2 points x 3 replicates of a world whose runs take about a tenth of a second (agents
// that rarely meet keep moving, so none sleeps), so a signal sent when the first run
// completes lands in the middle of the sweep, even on a loaded machine. (With an 80 x 80
// arena and 300 tu the whole sweep took tens of milliseconds once aggregates slept: a kill
// delayed on a loaded machine could land after its end.)
const char* kSlowSweep = R"(base: worlds/slow.yaml
parameters:
  robots.count: [30, 40]
  controller.p_leave: [0.001, 0.01]
replicates: 3
seed: 21
)";

const char* kSlowWorld = R"(name: slow
arena: {width: 400, height: 400}
robots: {count: 40}
controller: {type: bayindir}
run: {duration: 3000, record_every: 1000}
)";

class SweepCommandTest : public testing::SweepTest {
 protected:
  void SetUp() override {
    SweepTest::SetUp();
    testing::write_file_text(dir_ / "worlds" / "slow.yaml", kSlowWorld);
  }

  // Starts swarmagg with `arguments`, stdout and stderr into <dir>/output.txt.
  pid_t start(const std::vector<std::string>& arguments) {
    std::vector<std::string> words = {SWARMAGG_BINARY};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string output = (dir_ / "output.txt").string();
    posix_spawn_file_actions_addopen(&actions, 1, output.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid = 0;
    EXPECT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);
    return pid;
  }

  // The exit code, or 128 + the signal that killed it.
  static int wait_for(pid_t pid) {
    int status = 0;
    EXPECT_EQ(waitpid(pid, &status, 0), pid);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

  int swarmagg(const std::vector<std::string>& arguments) { return wait_for(start(arguments)); }
  std::string output() const { return read_file_text(dir_ / "output.txt"); }

  // Counts while the sweep may still be writing: its check that the folder is writable makes
  // the folder and removes it again, and a run's folder may vanish while it is read, so a
  // folder gone mid-count ends the count instead of throwing.
  int count_files(const std::string& out, const std::string& ending) const {
    int count = 0;
    std::error_code gone;
    std::filesystem::recursive_directory_iterator entry(dir_ / out, gone);
    for (; !gone && entry != std::filesystem::recursive_directory_iterator(); entry.increment(gone))
      count += entry->path().filename().string().ends_with(ending) ? 1 : 0;
    return count;
  }

  // Starts the slow sweep, sends `signal` once its first run is complete, returns the exit code.
  int kill_in_the_middle(const std::string& out, int signal) {
    const pid_t pid = start({"sweep", sweep_file(kSlowSweep), "--out", (dir_ / out).string(),
                             "--threads", "2", "--quiet", "--no-plots"});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (count_files(out, "world.resolved.yaml") == 0 &&
           std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ::kill(pid, signal);
    return wait_for(pid);
  }

  void expect_merged_like_an_uninterrupted_sweep(const std::string& out) {
    ASSERT_EQ(
        swarmagg({"sweep", sweep_file(kSlowSweep), "--out", (dir_ / out).string(), "--no-plots"}),
        0)
        << output();
    EXPECT_THAT(output(), HasSubstr("already complete"));
    const std::filesystem::path& reference = uninterrupted_reference();
    for (const char* file : {"sweep_timeseries.csv", "sweep_summary.csv", "sweep.json"}) {
      EXPECT_TRUE(read_file_text(dir_ / out / file) == read_file_text(reference / file)) << file;
    }
  }

  // The slow sweep run once without interruption, shared by the tests of this suite.
  const std::filesystem::path& uninterrupted_reference() {
    if (reference_.empty()) {
      const std::filesystem::path dir = dir_ / "reference";
      EXPECT_EQ(swarmagg({"sweep", sweep_file(kSlowSweep), "--out", dir.string(), "--quiet",
                          "--no-plots"}),
                0);
      reference_ = std::filesystem::temp_directory_path() /
                   ("swarmagg-sweep-reference-" + std::to_string(::getpid()));
      std::filesystem::create_directories(reference_);
      for (const char* file : {"sweep_timeseries.csv", "sweep_summary.csv", "sweep.json"}) {
        std::filesystem::copy_file(dir / file, reference_ / file);
      }
    }
    return reference_;
  }

  static void TearDownTestSuite() {
    if (!reference_.empty()) std::filesystem::remove_all(reference_);
    reference_.clear();  // --gtest_repeat runs the suite again in this process
  }

  static inline std::filesystem::path reference_;
};

TEST_F(SweepCommandTest, SigintKeepsCompletedRunsAndResumingGivesTheSameResult) {
  EXPECT_EQ(kill_in_the_middle("out", SIGINT), 130) << output();
  EXPECT_THAT(output(), HasSubstr("interrupted"));
  const int complete = count_files("out", "world.resolved.yaml");
  EXPECT_GE(complete, 1);
  EXPECT_LT(complete, 12);
  // Interrupted runs leave nothing: every run folder present is complete, no temporaries.
  EXPECT_EQ(count_files("out", "timeseries.csv"), complete);
  EXPECT_EQ(count_files("out", ".tmp"), 0);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out" / "sweep_timeseries.csv"));
  expect_merged_like_an_uninterrupted_sweep("out");
}

TEST_F(SweepCommandTest, SigtermExits143) {
  EXPECT_EQ(kill_in_the_middle("out", SIGTERM), 143) << output();
  EXPECT_EQ(count_files("out", ".tmp"), 0);
}

TEST_F(SweepCommandTest, ASweepKilledOutrightResumesToTheSameResult) {
  EXPECT_EQ(kill_in_the_middle("out", SIGKILL), 128 + SIGKILL);
  EXPECT_LT(count_files("out", "world.resolved.yaml"), 12);
  expect_merged_like_an_uninterrupted_sweep("out");
}

// Each run's own plots cost more than a short run: by default only the merged sweep's are
// drawn, and --run-plots adds each run's.
TEST_F(SweepCommandTest, TheMergedSweepGetsItsPlotsAndEachRunOnlyWhenAsked) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  const std::string sweep =
      sweep_file("base: worlds/tiny.yaml\nparameters:\n  robots.count: [10, 20]\nreplicates: 1\n");
  ASSERT_EQ(swarmagg({"sweep", sweep, "--out", (dir_ / "out").string()}), 0) << output();
  EXPECT_EQ(count_files("out", "noa.png"), 0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "final-noa-vs-robots.count.png"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "plots" / "final-noa-vs-robots.count.gp"));
  ASSERT_EQ(swarmagg({"sweep", sweep, "--run-plots", "--out", (dir_ / "drawn").string()}), 0)
      << output();
  EXPECT_EQ(count_files("drawn", "noa.png"), 2);
  EXPECT_EQ(count_files("drawn", "noa.gp"), 2);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "drawn" / "final-noa-vs-robots.count.png"));
}

TEST_F(SweepCommandTest, AResumedSweepWithNothingLeftPrintsNoEmptyProgressLine) {
  const std::string sweep =
      sweep_file("base: worlds/tiny.yaml\nparameters:\n  robots.count: [10, 20]\nreplicates: 1\n");
  const std::string out = (dir_ / "out").string();
  ASSERT_EQ(swarmagg({"sweep", sweep, "--out", out, "--no-plots"}), 0) << output();
  ASSERT_EQ(swarmagg({"sweep", sweep, "--out", out, "--no-plots", "--progress", "always"}), 0)
      << output();
  EXPECT_THAT(output(), HasSubstr("already complete"));
  EXPECT_THAT(output(), ::testing::Not(HasSubstr("0/0 runs")));
}

TEST_F(SweepCommandTest, ShardsThenMergeMatchTheUnshardedSweep) {
  const std::string sweep = sweep_file(testing::kGridSweep);
  ASSERT_EQ(swarmagg({"sweep", sweep, "--out", (dir_ / "full").string(), "--no-plots"}), 0)
      << output();
  EXPECT_THAT(output(), HasSubstr("merged 12 runs"));
  std::vector<std::string> merge = {"merge"};
  for (const char* shard : {"1/3", "2/3", "3/3"}) {
    const std::string out = (dir_ / ("shard-" + std::string(1, shard[0]))).string();
    ASSERT_EQ(swarmagg({"sweep", sweep, "--shard", shard, "--out", out, "--no-plots"}), 0)
        << output();
    EXPECT_THAT(output(), HasSubstr("(shard " + std::string(shard) + "): 4 runs"));
    merge.push_back(out);
  }
  merge.insert(merge.end(), {"--out", (dir_ / "merged").string()});
  ASSERT_EQ(swarmagg(merge), 0) << output();
  EXPECT_THAT(output(), HasSubstr("merged 12 runs (6 parameter points)"));
  for (const char* file : {"sweep_timeseries.csv", "sweep_summary.csv", "sweep.json"}) {
    EXPECT_TRUE(read_file_text(dir_ / "full" / file) == read_file_text(dir_ / "merged" / file))
        << file;
  }
}

TEST_F(SweepCommandTest, ListPrintsTheRunsWithoutRunningThem) {
  ASSERT_EQ(swarmagg({"sweep", sweep_file(testing::kGridSweep), "--list", "--shard", "3/3", "--out",
                      (dir_ / "out").string()}),
            0);
  const std::string text = output();
  EXPECT_THAT(text, HasSubstr("run replicate"));
  EXPECT_THAT(text, HasSubstr("pending     robots.count=20 controller.p_leave=0.005\n"));
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 4);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "out"));
}

TEST_F(SweepCommandTest, BadInputExits2WithAClearMessage) {
  EXPECT_EQ(
      swarmagg({"sweep", sweep_file("base: worlds/tiny.yaml\nparameters:\n  robots.cont: [1]\n")}),
      2);
  EXPECT_THAT(output(), HasSubstr("grid.yaml:3:3: parameters: unknown world key 'robots.cont' "
                                  "(did you mean 'robots.count'?)"));
  EXPECT_EQ(
      swarmagg({"sweep", sweep_file("base: worlds/tiny.yaml\nparameters:\n  robots.count: []\n")}),
      2);
  EXPECT_THAT(output(), HasSubstr("robots.count: expected a non-empty list of values"));
  EXPECT_EQ(swarmagg({"sweep", sweep_file(testing::kGridSweep), "--shard", "0/2"}), 2);
  EXPECT_THAT(output(), HasSubstr("--shard 0/2: expected i/n"));
  EXPECT_EQ(swarmagg({"sweep", sweep_file(testing::kGridSweep), "--threads", "-1"}), 2);
  EXPECT_EQ(swarmagg({"merge", (dir_ / "nowhere").string(), "--out", (dir_ / "m").string()}), 2);
  EXPECT_THAT(output(), HasSubstr("not a sweep output folder"));
}

}  // namespace
}  // namespace swarmagg
