// A run's rows spooled to disk while it runs: the same timeseries.csv as rows held, for any
// thread count, and nothing left behind by a run that does not finish.
#include "run/timeseries_spool.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/world_loader.hpp"
#include "output/timeseries_csv.hpp"
#include "run/run_folder.hpp"
#include "run/world_runner.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

WorldSpec small_world() {
  return load_world_text(R"(
name: spool
arena: {width: 60, height: 60}
robots: {count: 30}
controller: {type: bayindir, p_leave: 0.005, leave_timeout: 5}
run: {duration: 80, replicates: 3, seed: 9, record_every: 3}
)",
                         "test");
}

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::size_t entries_in(const std::filesystem::path& folder) {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++count;
  return count;
}

TEST(TimeseriesSpool, GivesTheFileOfTheRowsHeldForAnyThreadCount) {
  const WorldSpec spec = small_world();
  const std::string held = timeseries_csv(all_rows(run_world(spec, RunOptions{})));
  for (const int threads : {1, 3}) {
    const testing::ScratchDir dir("spool");
    const std::size_t open_files = entries_in("/proc/self/fd");
    TimeseriesSpool spool(dir.path() / "timeseries.csv", spec.run.replicates);
    RunOptions options;
    options.threads = threads;
    options.timeseries = &spool;
    const RunResult spooled = run_world(spec, options);
    // Closed as each replicate ends: a run of thousands of replicates holds few files open.
    EXPECT_EQ(entries_in("/proc/self/fd"), open_files);
    for (const ReplicateOutcome& r : spooled.replicates) {
      EXPECT_TRUE(r.rows.empty()) << "rows held as well as spooled";
      EXPECT_EQ(r.final_row.step, spec.steps());
    }
    EXPECT_EQ(entries_in(dir.path()), 3u) << "one temporary per replicate";
    write_run_folder(spec, spooled, dir.path(), {}, &spool);
    EXPECT_EQ(text_of(dir.path() / "timeseries.csv"), held) << threads << " threads";
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      EXPECT_FALSE(entry.path().filename().string().ends_with(".tmp")) << entry.path();
  }
}

// The final row, kept either way, is what the summaries read: spooled, it is the last row
// the held run has.
TEST(TimeseriesSpool, ASpooledRunKeepsTheLastRowOfEachReplicate) {
  const WorldSpec spec = small_world();
  const RunResult held = run_world(spec, RunOptions{});
  const testing::ScratchDir dir("spool");
  TimeseriesSpool spool(dir.path() / "timeseries.csv", spec.run.replicates);
  RunOptions options;
  options.timeseries = &spool;
  const RunResult spooled = run_world(spec, options);
  ASSERT_EQ(spooled.replicates.size(), held.replicates.size());
  for (std::size_t r = 0; r < held.replicates.size(); ++r) {
    EXPECT_EQ(timeseries_csv_line(spooled.replicates[r].final_row),
              timeseries_csv_line(held.replicates[r].rows.back()))
        << r;
  }
}

// Rows dropped (`rates`): none held, none spooled, and the final rows as a held run's.
TEST(TimeseriesSpool, ARunKeepingNoRowsStillKeepsTheLastRowOfEachReplicate) {
  const WorldSpec spec = small_world();
  const RunResult held = run_world(spec, RunOptions{});
  RunOptions options;
  options.keep_rows = false;
  const RunResult dropped = run_world(spec, options);
  for (std::size_t r = 0; r < held.replicates.size(); ++r) {
    EXPECT_TRUE(dropped.replicates[r].rows.empty());
    EXPECT_EQ(timeseries_csv_line(dropped.replicates[r].final_row),
              timeseries_csv_line(held.replicates[r].rows.back()))
        << r;
  }
}

// Temporaries kept in another folder than the target's (`compare`, whose arm folders an
// earlier comparison holds until the new one is written): the target's folder is made at
// commit() only, and the file is the same.
TEST(TimeseriesSpool, PartsInAnotherFolderGiveTheSameFile) {
  const WorldSpec spec = small_world();
  const std::string held = timeseries_csv(all_rows(run_world(spec, RunOptions{})));
  const testing::ScratchDir dir("spool");
  const std::filesystem::path target = dir.path() / "arm" / "timeseries.csv";
  TimeseriesSpool spool(target, spec.run.replicates, dir.path());
  RunOptions options;
  options.timeseries = &spool;
  const RunResult spooled = run_world(spec, options);
  EXPECT_FALSE(std::filesystem::exists(target.parent_path()));
  EXPECT_EQ(entries_in(dir.path()), 3u) << "one temporary per replicate, beside the arm";
  spool.commit();
  EXPECT_EQ(text_of(target), held);
  EXPECT_EQ(entries_in(dir.path()), 1u) << "the temporaries are gone";
}

TEST(TimeseriesSpool, ASpoolNeverCommittedLeavesNothingAndTheEarlierFile) {
  const testing::ScratchDir dir("spool");
  std::ofstream(dir.path() / "timeseries.csv") << "earlier\n";
  {
    TimeseriesSpool spool(dir.path() / "timeseries.csv", 2);
    spool.append(1, TimeseriesRow{});
    EXPECT_EQ(entries_in(dir.path()), 2u) << "a replicate's temporary opens at its first row";
  }
  EXPECT_EQ(entries_in(dir.path()), 1u);
  EXPECT_EQ(text_of(dir.path() / "timeseries.csv"), "earlier\n");
}

}  // namespace
}  // namespace swarmagg
