#include "sweep/sweep_merge.hpp"

#include <gmock/gmock.h>

#include <csignal>
#include <fstream>

#include "core/errors.hpp"
#include "run/interrupt.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_manifest.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_summary.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using testing::read_file_text;
using ::testing::StartsWith;

const std::vector<std::string> kMergedFiles = {"sweep_timeseries.csv", "sweep_summary.csv",
                                               "sweep.json"};

class SweepMergeTest : public testing::SweepTest {
 protected:
  void run(const std::string& sweep, const std::string& out, Shard shard = {}, int threads = 2) {
    SweepOptions options;
    options.out = dir_ / out;
    options.shard = shard;
    options.threads = threads;
    run_sweep(load_sweep(sweep_file(sweep)), options);
  }

  void expect_same_files(const std::string& a, const std::string& b,
                         const std::vector<std::string>& files = kMergedFiles) {
    for (const std::string& file : files) {
      const std::string expected = read_file_text(dir_ / a / file);
      EXPECT_FALSE(expected.empty()) << file;
      EXPECT_TRUE(read_file_text(dir_ / b / file) == expected) << file << " differs";
    }
  }
};

TEST_F(SweepMergeTest, ShardsMergeToTheUnshardedSweepByteForByte) {
  run(testing::kGridSweep, "full");
  merge_sweep({dir_ / "full"}, dir_ / "full-merged");
  for (int i = 1; i <= 3; ++i)
    run(testing::kGridSweep, "shard-" + std::to_string(i), Shard{i, 3}, i);
  const MergeReport report =
      merge_sweep({dir_ / "shard-1", dir_ / "shard-2", dir_ / "shard-3"}, dir_ / "shards-merged");
  EXPECT_EQ(report.runs, 12);
  EXPECT_EQ(report.points, 6);
  expect_same_files("full-merged", "shards-merged");
  // The order of the folders does not matter either.
  merge_sweep({dir_ / "shard-3", dir_ / "shard-1", dir_ / "shard-2"}, dir_ / "reordered");
  expect_same_files("full-merged", "reordered");
}

// A merge into another sweep's merged folder, or into a run's folder, would mix their files
// with its own: refused unless forced. The earlier merge's plots go when they drew another
// summary. Other files stay: the shards' folders and logs, as examples/slurm/submit.sh merges.
TEST_F(SweepMergeTest, AnotherSweepsFolderOrARunAreMergedIntoOnlyWithForce) {
  run(testing::kGridSweep, "full");
  merge_sweep({dir_ / "full"}, dir_ / "m");
  for (const char* name : {"final-noa-vs-robots.count.png", "plots/final-noa-vs-robots.count.gp",
                           "sweep_partitions.csv", "logs/slurm-1.out", "final-noa-vs-mine.png"})
    testing::write_file_text(dir_ / "m" / name, "earlier\n");
  // Plots are named by the earlier summary's world keys only: an edited column cannot name
  // a file outside the folder.
  testing::write_file_text(dir_ / "victim.png", "yours\n");
  const std::string summary = read_file_text(dir_ / "m" / "sweep_summary.csv");
  testing::write_file_text(dir_ / "m" / "sweep_summary.csv", "../../../victim," + summary);
  merge_sweep({dir_ / "full"}, dir_ / "m");
  EXPECT_TRUE(std::filesystem::exists(dir_ / "victim.png"));
  for (const char* name : {"final-noa-vs-robots.count.png", "plots/final-noa-vs-robots.count.gp",
                           "sweep_partitions.csv"})
    testing::write_file_text(dir_ / "m" / name, "earlier\n");
  // The same sweep merged again draws the same plots: they stay, and so do other files.
  EXPECT_THAT(merge_sweep({dir_ / "full"}, dir_ / "m").removed,
              ::testing::ElementsAre(dir_ / "m" / "sweep_partitions.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "m" / "final-noa-vs-robots.count.png"));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "m" / "logs" / "slurm-1.out"));
  run("name: other\nbase: worlds/tiny.yaml\nparameters:\n  robots.count: [10]\nreplicates: 1\n"
      "seed: 1\n",
      "o");
  EXPECT_THAT([&] { merge_sweep({dir_ / "o"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("m/ holds the sweep 'grid', not 'other': pass --force")));
  EXPECT_TRUE(std::filesystem::exists(dir_ / "m" / "final-noa-vs-robots.count.png"));
  EXPECT_EQ(merge_sweep({dir_ / "o"}, dir_ / "m", true).removed.size(), 2u);
  EXPECT_EQ(read_manifest(dir_ / "m").name, "other");
  for (const char* name : {"final-noa-vs-robots.count.png", "plots/final-noa-vs-robots.count.gp"})
    EXPECT_FALSE(std::filesystem::exists(dir_ / "m" / name)) << name;
  EXPECT_TRUE(std::filesystem::exists(dir_ / "m" / "final-noa-vs-mine.png")) << "yours stay";
  // The same sweep merges again without --force (more shards done since, say).
  merge_sweep({dir_ / "o"}, dir_ / "m");
  testing::write_file_text(dir_ / "run" / "timeseries.csv", "a run's\n");
  testing::write_file_text(dir_ / "run" / "world.resolved.yaml", "name: tiny\n");
  EXPECT_THAT([&] { merge_sweep({dir_ / "o"}, dir_ / "run"); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr("run/ holds a run (world.resolved.yaml): pass --force")));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "run" / "sweep_summary.csv"));
  merge_sweep({dir_ / "o"}, dir_ / "run", true);
  EXPECT_TRUE(std::filesystem::exists(dir_ / "run" / "sweep_summary.csv"));
  EXPECT_EQ(read_file_text(dir_ / "run" / "timeseries.csv"), "a run's\n");
}

TEST_F(SweepMergeTest, TheTimeseriesIsTidyWithParametersFirst) {
  run(testing::kGridSweep, "full");
  merge_sweep({dir_ / "full"}, dir_ / "merged");
  const std::string text = read_file_text(dir_ / "merged" / "sweep_timeseries.csv");
  EXPECT_THAT(text, StartsWith("robots.count,controller.p_leave,replicate,step,time,noa,"));
  // Each run records steps 0, 50, ..., 1000: 21 rows; 12 runs.
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 12 * 21);
  // Run 3 is point (10, 0.001), replicate 1: its rows are its own timeseries.csv rows with
  // the parameters prepended and the sweep's replicate index in place of 0.
  std::istringstream own(read_file_text(
      dir_ / "full/runs/robots.count=10,controller.p_leave=0.001/rep-1/timeseries.csv"));
  std::string line;
  std::getline(own, line);  // header
  while (std::getline(own, line)) {
    ASSERT_THAT(line, StartsWith("0,"));
    EXPECT_THAT(text, HasSubstr("\n10,0.001,1," + line.substr(2) + "\n"));
  }
}

TEST_F(SweepMergeTest, RefusesMissingRunsAndForeignSweeps) {
  run(testing::kGridSweep, "shard-1", Shard{1, 3});
  run(testing::kGridSweep, "shard-2", Shard{2, 3});
  EXPECT_THAT(
      [&] {
        merge_sweep({dir_ / "shard-1", dir_ / "shard-2"}, dir_ / "m");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("4 of 12 runs are not complete")));
  std::string other = testing::kGridSweep;
  other.replace(other.find("seed: 7"), 7, "seed: 8");
  run(other, "other", Shard{3, 3});
  EXPECT_THAT(
      [&] {
        merge_sweep({dir_ / "shard-1", dir_ / "shard-2", dir_ / "other"}, dir_ / "m");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("holds a different sweep")));
  EXPECT_THAT([&] { merge_sweep({dir_ / "nowhere"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("not a sweep output folder")));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "m"));
}

TEST_F(SweepMergeTest, RefusesAShardFileWithADamagedRow) {
  run(testing::kGridSweep, "full");
  const std::filesystem::path file =
      dir_ / "full/runs/robots.count=10,controller.p_leave=0.001/rep-1/timeseries.csv";
  const std::string good = read_file_text(file);
  // Line 3's noa cell (column 4) made a word, then the line cut short after its time.
  const std::size_t line3 = good.find('\n', good.find('\n') + 1) + 1;
  const std::size_t noa = good.find(',', good.find(',', good.find(',', line3) + 1) + 1) + 1;
  std::string damaged = good;
  damaged.replace(noa, good.find(',', noa) - noa, "many");
  std::ofstream(file, std::ios::binary) << damaged;
  EXPECT_THAT([&] { merge_sweep({dir_ / "full"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(
                  AllOf(HasSubstr(file.string() + ":3"), HasSubstr("'noa'"), HasSubstr("'many'"))));
  damaged = good;
  damaged.replace(noa, good.find(',', noa) - noa, "inf");
  std::ofstream(file, std::ios::binary) << damaged;
  EXPECT_THAT([&] { merge_sweep({dir_ / "full"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(AllOf(
                  HasSubstr(file.string() + ":3"), HasSubstr("expected a whole number >= 0"))));
  std::ofstream(file, std::ios::binary) << good.substr(0, good.find(',', noa - 1) + 0);
  EXPECT_THAT([&] { merge_sweep({dir_ / "full"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr(file.string() + ":3")));
  // Cut short at a line's end: every row is whole, but the run's last steps are missing.
  std::ofstream(file, std::ios::binary) << good.substr(0, line3);
  EXPECT_THAT([&] { merge_sweep({dir_ / "full"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(
                  AllOf(HasSubstr(file.string() + ": holds 1 row but the run records 21 states"),
                        HasSubstr("cut short"))));
  // A row in the middle missing, or the last repeated: each row must be the next state the run
  // records (they were merged as they stood; plot refused them).
  const std::size_t line4 = good.find('\n', line3) + 1;
  std::ofstream(file, std::ios::binary) << good.substr(0, line3) << good.substr(line4);
  EXPECT_THAT([&] { merge_sweep({dir_ / "full"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(
                  AllOf(HasSubstr(file.string() + ":3: expected replicate 0 at step 50"),
                        HasSubstr("got replicate 0 at step 100"))));
  const std::string last = good.substr(good.rfind('\n', good.size() - 2) + 1);
  std::ofstream(file, std::ios::binary) << good << last;
  EXPECT_THAT([&] { merge_sweep({dir_ / "full"}, dir_ / "m"); },
              ::testing::ThrowsMessage<InputError>(
                  HasSubstr(file.string() + ":23: a row after the run's last recorded state")));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "m"));
}

// Every row a run records, when its last step is off the record grid (205 steps, every 7: steps
// 0, 7, ..., 203 and 205) or the grid is coarser than the run (its first and last only).
TEST_F(SweepMergeTest, RunsWhoseLastStepIsOffTheRecordGridMerge) {
  for (const char* record_every : {"7", "500"}) {
    const std::string out = std::string("grid-") + record_every;
    run(std::string("base: worlds/tiny.yaml\nparameters:\n  run.record_every: [") + record_every +
            "]\n  run.duration: [20.5]\nreplicates: 2\n",
        out);
    const MergeReport merged = merge_sweep({dir_ / out}, dir_ / (out + "-merged"));
    EXPECT_EQ(merged.runs, 2) << record_every;
    const std::string text = read_file_text(dir_ / (out + "-merged") / "sweep_timeseries.csv");
    const auto lines = std::count(text.begin(), text.end(), '\n');
    EXPECT_EQ(lines, 1 + 2 * (record_every == std::string("7") ? 31 : 2)) << record_every;
  }
}

// The merged rows are written while the shard files are read: a damaged file found late
// discards what was written and leaves the earlier merge whole, with no temporary beside it.
TEST_F(SweepMergeTest, ARefusedMergeLeavesTheEarlierMergedFilesAsTheyWere) {
  run(testing::kGridSweep, "full");
  merge_sweep({dir_ / "full"}, dir_ / "m");
  std::vector<std::string> earlier;
  for (const std::string& file : kMergedFiles) earlier.push_back(read_file_text(dir_ / "m" / file));
  // The last run in merge order, so that every other run's rows were written before.
  const std::filesystem::path file =
      dir_ / "full/runs/robots.count=20,controller.p_leave=0.005/rep-1/timeseries.csv";
  const std::string good = read_file_text(file);
  ASSERT_FALSE(good.empty());
  std::ofstream(file, std::ios::binary) << good.substr(0, good.rfind(',')) << ",x\n";
  EXPECT_THROW(merge_sweep({dir_ / "full"}, dir_ / "m"), InputError);
  for (std::size_t k = 0; k < kMergedFiles.size(); ++k)
    EXPECT_TRUE(read_file_text(dir_ / "m" / kMergedFiles[k]) == earlier[k]) << kMergedFiles[k];
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir_ / "m"))
    ++files;
  EXPECT_EQ(files, kMergedFiles.size());
}

// Ctrl-C (or Slurm's SIGTERM) during a merge: the earlier merge stays whole, a new folder is
// not left behind, and no temporary is; one a killed merge left is removed by the next.
TEST_F(SweepMergeTest, AnInterruptedMergeLeavesNoTemporaryAndTheEarlierMerge) {
  run(testing::kGridSweep, "full");
  merge_sweep({dir_ / "full"}, dir_ / "m");
  std::vector<std::string> earlier;
  for (const std::string& file : kMergedFiles) earlier.push_back(read_file_text(dir_ / "m" / file));
  set_interrupt_signal(SIGINT);
  EXPECT_THROW(merge_sweep({dir_ / "full"}, dir_ / "m"), Interrupted);
  EXPECT_THROW(merge_sweep({dir_ / "full"}, dir_ / "new"), Interrupted);
  set_interrupt_signal(0);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "new"));
  for (std::size_t k = 0; k < kMergedFiles.size(); ++k)
    EXPECT_TRUE(read_file_text(dir_ / "m" / kMergedFiles[k]) == earlier[k]) << kMergedFiles[k];
  // Beyond Linux's largest process id: a merge killed outright.
  std::ofstream(dir_ / "m" / ".sweep_timeseries.csv.99999999.0.tmp") << "killed";
  merge_sweep({dir_ / "full"}, dir_ / "m");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir_ / "m"))
    ++files;
  EXPECT_EQ(files, kMergedFiles.size());
}

TEST_F(SweepMergeTest, SoysalPartitionsAreMergedToo) {
  run("base: worlds/tiny.yaml\nparameters:\n  controller.type: [soysal]\n  robots.count: [5, 8]\n"
      "replicates: 2\n",
      "soysal");
  merge_sweep({dir_ / "soysal"}, dir_ / "merged");
  const std::string text = read_file_text(dir_ / "merged" / "sweep_partitions.csv");
  EXPECT_THAT(text, StartsWith("controller.type,robots.count,replicate,partition,time_fraction\n"
                               "soysal,5,0,"));
  EXPECT_THAT(text, HasSubstr("\nsoysal,8,1,"));
}

TEST(SweepSummary, GivesMeanSdAndQuantilesPerPointAndObservable) {
  const std::string text =
      sweep_summary_csv({"robots.count"}, {"noa", "largest"},
                        {{{"10"}, {{1, 5}, {2, 5}, {3, 5}, {4, 5}}}, {{"20"}, {{7, 1}}}});
  EXPECT_EQ(text,
            "robots.count,observable,replicates,mean,sd,min,q25,median,q75,max\n"
            "10,noa,4,2.5,1.2909944487358056,1,1.75,2.5,3.25,4\n"
            "10,largest,4,5,0,5,5,5,5,5\n"
            "20,noa,1,7,0,7,7,7,7,7\n"
            "20,largest,1,1,0,1,1,1,1,1\n");
}

}  // namespace
}  // namespace swarmagg
