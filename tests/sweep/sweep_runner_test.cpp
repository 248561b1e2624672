#include "sweep/sweep_runner.hpp"

#include <gmock/gmock.h>

#include <csignal>

#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "output/timeseries_csv.hpp"
#include "run/interrupt.hpp"
#include "run/run_folder.hpp"
#include "sweep/sweep_listing.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_merge.hpp"
#include "sweep/sweep_status.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;
using testing::read_file_text;

class SweepRunnerTest : public testing::SweepTest {
 protected:
  void TearDown() override {
    set_interrupt_signal(0);  // even when a test failed while pretending a signal arrived
    SweepTest::TearDown();
  }

  SweepReport run(const std::string& out, int threads = 2, bool replace_outdated = false) {
    SweepOptions options;
    options.out = dir_ / out;
    options.threads = threads;
    options.replace_outdated = replace_outdated;
    return run_sweep(load_sweep(sweep_file(testing::kGridSweep)), options);
  }

  std::filesystem::path folder(const std::string& out, int run_index) {
    const auto runs = expand_sweep(load_sweep(sweep_file(testing::kGridSweep)));
    return sweep_run_folder(dir_ / out, runs[static_cast<std::size_t>(run_index)]);
  }

  static int count_files(const std::filesystem::path& root, const std::string& ending) {
    int count = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      count += entry.path().filename().string().ends_with(ending) ? 1 : 0;
    }
    return count;
  }
};

TEST_F(SweepRunnerTest, WritesEveryRunIntoItsOwnCompleteFolder) {
  const SweepReport report = run("out");
  EXPECT_EQ(report.selected, 12);
  EXPECT_EQ(report.ran, 12);
  EXPECT_EQ(count_files(dir_ / "out", "world.resolved.yaml"), 12);
  EXPECT_EQ(count_files(dir_ / "out", "timeseries.csv"), 12);
  EXPECT_EQ(count_files(dir_ / "out", ".tmp"), 0);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "out" / "sweep.json"));
}

TEST_F(SweepRunnerTest, ARunFolderReproducesItselfWithSwarmaggRun) {
  run("out");
  const auto run_folder = folder("out", 10);
  const WorldSpec world = load_world((run_folder / "world.resolved.yaml").string());
  EXPECT_EQ(world.run.replicates, 1);
  const RunResult again = run_world(world, RunOptions{});
  EXPECT_EQ(timeseries_csv(all_rows(again)), read_file_text(run_folder / "timeseries.csv"));
}

TEST_F(SweepRunnerTest, ResumingSkipsCompleteRunsAndRedoesUnfinishedOrOutdatedOnes) {
  run("out");
  merge_sweep({dir_ / "out"}, dir_ / "reference");
  // Run 4 was cut short mid-write (no resolved world, a half file, a temporary left over);
  // run 9 holds a world the sweep no longer asks for.
  std::filesystem::remove(folder("out", 4) / "world.resolved.yaml");
  testing::write_file_text(folder("out", 4) / "timeseries.csv", "replicate,st");
  testing::write_file_text(folder("out", 4) / ".summary.json.123.0.tmp", "{");
  const auto outdated = folder("out", 9) / "world.resolved.yaml";
  std::string world = read_file_text(outdated);
  world.replace(world.find("duration: 100"), 13, "duration: 90");
  testing::write_file_text(outdated, world);
  const auto runs = expand_sweep(load_sweep(sweep_file(testing::kGridSweep)));
  EXPECT_EQ(sweep_run_status(dir_ / "out", runs[4]), RunStatus::Unfinished);
  EXPECT_EQ(sweep_run_status(dir_ / "out", runs[9]), RunStatus::Outdated);
  EXPECT_EQ(sweep_run_status(dir_ / "out", runs[10]), RunStatus::Complete);
  EXPECT_EQ(sweep_run_status(dir_ / "nowhere", runs[10]), RunStatus::Pending);

  // An outdated run holds results someone may need: replaced only when asked.
  EXPECT_THAT([&] { run("out"); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("1 run holds results of another world (the base world, seed or values "
                            "changed since they ran), e.g. " +
                            folder("out", 9).string() + "; pass --force")));
  EXPECT_TRUE(read_file_text(outdated) == world) << "the outdated run was touched";
  const SweepReport report = run("out", 2, true);
  EXPECT_EQ(report.already_complete, 10);
  EXPECT_EQ(report.ran, 2);
  EXPECT_EQ(count_files(dir_ / "out", ".tmp"), 0);
  merge_sweep({dir_ / "out"}, dir_ / "out");
  for (const char* file : {"sweep_timeseries.csv", "sweep_summary.csv"}) {
    EXPECT_TRUE(read_file_text(dir_ / "out" / file) == read_file_text(dir_ / "reference" / file))
        << file;
  }
}

// Threads and frame settings change none of a run's outputs: a base world given them later
// keeps every run complete, and the sweep runs nothing again.
TEST_F(SweepRunnerTest, ThreadsOrFrameSettingsInTheBaseWorldLeaveItsRunsComplete) {
  run("out");
  testing::write_file_text(
      dir_ / "worlds" / "tiny.yaml",
      std::string(testing::kTinyWorld) + "render: {width: 640, height: 480}\n");
  std::string base = read_file_text(dir_ / "worlds" / "tiny.yaml");
  base.replace(base.find("record_every: 50}"), 17, "record_every: 50, threads: 1}");
  testing::write_file_text(dir_ / "worlds" / "tiny.yaml", base);
  const SweepReport report = run("out");
  EXPECT_EQ(report.already_complete, 12);
  EXPECT_EQ(report.ran, 0);
  base.replace(base.find("duration: 100"), 13, "duration: 90");
  testing::write_file_text(dir_ / "worlds" / "tiny.yaml", base);
  EXPECT_THROW(run("out"), InputError) << "a length that changes the results counts";
}

TEST_F(SweepRunnerTest, AFolderThatIsNotASweepsIsRefused) {
  std::filesystem::create_directories(dir_ / "a-run");
  testing::write_file_text(dir_ / "a-run" / "timeseries.csv", "replicate,step\n");
  EXPECT_THAT([&] { run("a-run"); }, ::testing::ThrowsMessage<InputError>(HasSubstr(
                                         "holds files but no sweep.json: not a sweep's folder")));
  // A shard that starts while another writes the manifest sees only its temporary.
  std::filesystem::create_directories(dir_ / "starting");
  testing::write_file_text(dir_ / "starting" / ".sweep.json.42.0.tmp", "{");
  EXPECT_EQ(run("starting").ran, 12);
  // Another sweep's folder (its manifest names another sweep) is not this one's.
  SweepOptions options;
  options.out = dir_ / "starting";
  const SweepPlan other = load_sweep(sweep_file(testing::kGridSweep, "other.yaml"));
  EXPECT_THAT([&] { run_sweep(other, options); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("holds the sweep 'grid', not 'other'; pass --force")));
}

TEST_F(SweepRunnerTest, AnInterruptStopsBeforeTheNextRunAndKeepsCompletedOnes) {
  run("out", 1);
  std::filesystem::remove_all(folder("out", 3));
  set_interrupt_signal(SIGTERM);
  try {
    run("out", 1);
    ADD_FAILURE() << "not interrupted";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.exit_code(), 143);
  }
  set_interrupt_signal(0);
  EXPECT_FALSE(std::filesystem::exists(folder("out", 3)));
  EXPECT_EQ(count_files(dir_ / "out", "world.resolved.yaml"), 11);
  EXPECT_EQ(run("out", 1).ran, 1);
}

TEST_F(SweepRunnerTest, TheListingShowsIndexSeedStatusAndParameters) {
  run("out");
  std::filesystem::remove_all(folder("out", 1));
  const auto runs = expand_sweep(load_sweep(sweep_file(testing::kGridSweep)));
  const std::string listing = sweep_listing(shard_runs(runs, Shard{2, 3}), dir_ / "out");
  EXPECT_THAT(listing, ::testing::StartsWith(
                           "   run replicate                 seed status      parameters\n"));
  EXPECT_THAT(listing, HasSubstr("     1         1 "));
  // Appended, not " " + std::to_string(...): see the precompiled header in tests/CMakeLists.txt.
  EXPECT_THAT(listing,
              HasSubstr(std::string(" ")
                            .append(std::to_string(runs[1].seed))
                            .append(" pending     robots.count=10 controller.p_leave=0.0005\n")));
  EXPECT_THAT(listing, HasSubstr(" complete    robots.count=10 controller.p_leave=0.005\n"));
  EXPECT_THAT(listing, HasSubstr("     4         0"));
  EXPECT_THAT(listing, ::testing::Not(HasSubstr("\n     3 ")));
  EXPECT_EQ(std::count(listing.begin(), listing.end(), '\n'), 1 + 4);
}

}  // namespace
}  // namespace swarmagg
