// `run --trajectories K` and `render RUN_DIR`, through the built binary: the stored
// aggregate ids agree with timeseries.csv, and re-rendered frames are byte-identical to the
// frames the run drew at the same steps.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <thread>

#include "analysis/csv_table.hpp"
#include "cli/cli_testing.hpp"
#include "output/trajectory_reader.hpp"

namespace swarmagg {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using Outcome = testing::CliOutcome;
using testing::read_all;

Outcome swarmagg(const std::string& arguments) {
  return testing::run_swarmagg(arguments);
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("swarmagg-trajectories-" + name);
  fs::remove_all(dir);
  return dir;
}

// NOA of timeseries.csv by (replicate, step).
std::map<std::pair<int, std::int64_t>, int> recorded_noa(const fs::path& csv) {
  const CsvTable table = read_csv(csv);
  const std::size_t replicate = table.column("replicate");
  const std::size_t step = table.column("step");
  const std::size_t noa_column = table.column("noa");
  std::map<std::pair<int, std::int64_t>, int> noa;
  for (std::size_t row = 0; row < table.rows.size(); ++row) {
    noa[{static_cast<int>(table.number(row, replicate)),
         static_cast<std::int64_t>(table.number(row, step))}] =
        static_cast<int>(table.number(row, noa_column));
  }
  return noa;
}

// The demo world (full model: aggregates form, grow, shrink and dissolve), shortened.
const std::string kWorld =
    "worlds/examples/demo.yaml --replicates 2 --threads 2 --set run.duration=150 --no-model "
    "--quiet";

TEST(Trajectories, AggregateIdsAgreeWithTheTimeseriesAtEveryStoredStep) {
  const fs::path out = fresh_dir("noa");
  const Outcome o = swarmagg("run " + kWorld + " --trajectories 10 --out " + out.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  const TrajectoryReader reader(out / "trajectories.h5");
  EXPECT_EQ(reader.every(), 10);
  EXPECT_EQ(reader.agents(), 60);
  EXPECT_THAT(reader.world_text(), HasSubstr("trajectories: 10"));
  EXPECT_EQ(reader.world_text(), read_all(out / "world.resolved.yaml"));
  const auto noa = recorded_noa(out / "timeseries.csv");
  int compared = 0, aggregated = 0;
  for (int r = 0; r < 2; ++r) {
    const auto steps = reader.steps(r);
    ASSERT_EQ(steps.size(), 151u) << "steps 0, 10, ..., 1500";
    TrajectoryRow row;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      reader.read(r, static_cast<std::int64_t>(i), row);
      std::set<std::int32_t> ids;
      for (const std::int32_t id : row.aggregate) {
        if (id >= 0) ids.insert(id);
      }
      const auto recorded = noa.find({r, row.step});
      ASSERT_NE(recorded, noa.end()) << "step " << row.step << " not in timeseries.csv";
      EXPECT_EQ(static_cast<int>(ids.size()), recorded->second)
          << "replicate " << r << " step " << row.step;
      ++compared;
      aggregated += ids.empty() ? 0 : 1;
    }
  }
  EXPECT_EQ(compared, 302);
  EXPECT_GT(aggregated, 100) << "the test needs steps with aggregates to mean anything";
  fs::remove_all(out);
}

TEST(Trajectories, ReRenderedFramesAreByteIdenticalToTheRunsFrames) {
  const fs::path out = fresh_dir("render");
  const Outcome run = swarmagg("run " + kWorld +
                               " --trajectories 10 --render-every 300 --render-size 200x160 "
                               "--render-replicate 1 --out " +
                               out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const Outcome render = swarmagg("render " + out.string() + " --every 300 --quiet --out " +
                                  (out / "replay").string());
  ASSERT_EQ(render.exit_code, 0) << render.output;
  int frames = 0;
  for (const auto& entry : fs::directory_iterator(out / "frames")) {
    const fs::path replay = out / "replay" / entry.path().filename();
    ASSERT_TRUE(fs::exists(replay)) << replay;
    EXPECT_TRUE(read_all(entry.path()) == read_all(replay)) << entry.path().filename();
    ++frames;
  }
  EXPECT_EQ(frames, 6) << "steps 0, 300, ..., 1500";
  EXPECT_EQ(std::distance(fs::directory_iterator(out / "replay"), fs::directory_iterator{}), 6);
  // Another replicate draws other frames.
  ASSERT_EQ(swarmagg("render " + out.string() + " --every 300 --replicate 0 --quiet --out " +
                     (out / "other").string())
                .exit_code,
            0);
  EXPECT_FALSE(read_all(out / "frames" / "frame_000005.png") ==
               read_all(out / "other" / "frame_000005.png"));
  fs::remove_all(out);
}

TEST(Trajectories, BadRenderRequestsExitTwoWithAReason) {
  const fs::path out = fresh_dir("bad");
  Outcome o = swarmagg("render " + out.string());
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_THAT(o.output, HasSubstr("trajectories.h5"));
  ASSERT_EQ(
      swarmagg("run worlds/examples/demo.yaml --replicates 2 --no-model --quiet --trajectories 10 "
               "--set run.duration=5 --out " +
               out.string())
          .exit_code,
      0);
  o = swarmagg("render " + out.string() + " --every 15");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_THAT(o.output, HasSubstr("multiple of 10"));
  o = swarmagg("render " + out.string() + " --replicate 2");
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_THAT(o.output, HasSubstr("no replicate 2"));
  o = swarmagg("run " + kWorld + " --trajectories -1 --force --out " + out.string());
  EXPECT_EQ(o.exit_code, 2);
  EXPECT_THAT(o.output, HasSubstr("run.trajectories"));
  fs::remove_all(out);
}

TEST(Trajectories, ARunWithoutTrajectoriesRemovesAnEarlierFile) {
  const fs::path out = fresh_dir("stale");
  ASSERT_EQ(swarmagg("run " + kWorld + " --trajectories 10 --out " + out.string()).exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "trajectories.h5"));
  ASSERT_EQ(swarmagg("run " + kWorld + " --force --out " + out.string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "trajectories.h5")) << "would not belong to the new run";
  fs::remove_all(out);
}

// The trajectories.h5 of the small demo run with several replicates, on `threads` threads.
std::string stored_file(const fs::path& folder, int threads) {
  std::string arguments =
      "run worlds/examples/demo.yaml --replicates 4 --set run.duration=150 --trajectories 10 "
      "--no-model --no-plots --quiet --threads ";
  arguments.append(std::to_string(threads)).append(" --out ").append(folder.string());
  const Outcome o = swarmagg(arguments);
  EXPECT_EQ(o.exit_code, 0) << o.output;
  return read_all(folder / "trajectories.h5");
}

// The same run on one thread writes the same bytes (HDF5 would stamp each object with its
// creation time).
TEST(Trajectories, TheSameRunOnOneThreadWritesTheSameFile) {
  const fs::path out = fresh_dir("same-bytes");
  const std::string first = stored_file(out / "0", 1);
  // HDF5's times have a resolution of a second: the second file is written in another.
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  const std::string second = stored_file(out / "1", 1);
  EXPECT_FALSE(first.empty());
  EXPECT_TRUE(first == second) << "the two files differ";
  fs::remove_all(out);
}

// The file with the thread count that its `world` attribute records (world.resolved.yaml
// records it too) written as 1. The texts are the same length, so nothing else moves.
std::string as_if_on_one_thread(std::string file, int threads) {
  std::string recorded = "\n  threads: ";
  recorded.append(std::to_string(threads)).append("\n");
  const std::size_t at = file.find(recorded);
  EXPECT_NE(at, std::string::npos) << "no threads line in the stored world";
  if (at != std::string::npos) file.replace(at, recorded.size(), "\n  threads: 1\n");
  return file;
}

// With replicates in parallel they finish in another order than on one thread; the file is
// the same, byte for byte.
TEST(Trajectories, AnyNumberOfThreadsWritesTheSameFile) {
  const fs::path out = fresh_dir("threads");
  const std::string one = stored_file(out / "1", 1);
  EXPECT_FALSE(one.empty());
  for (const int threads : {2, 3}) {
    const std::string many = stored_file(out / std::to_string(threads), threads);
    EXPECT_TRUE(as_if_on_one_thread(many, threads) == one)
        << threads << " threads wrote another file than one thread";
  }
  fs::remove_all(out);
}

// A disk that fills while the replicates are copied into trajectories.h5 (HDF5's copy crashed
// on its error path): a clear error, exit 1, and nothing left in the run folder. Needs a small
// tmpfs, so root and a kernel that lets the test mount one.
TEST(Trajectories, ADiskThatFillsDuringTheCopyIsAnErrorAndLeavesNothing) {
  const fs::path disk = fresh_dir("full-disk");
  fs::create_directories(disk);
  const std::string mount =
      "mount -t tmpfs -o size=1600k tmpfs '" + disk.string() + "' 2>/dev/null";
  if (::geteuid() != 0 || std::system(mount.c_str()) != 0) GTEST_SKIP() << "cannot mount a tmpfs";
  const Outcome o = swarmagg(
      "run worlds/examples/demo.yaml --no-plots --replicates 3 --threads 2 "
      "--set run.duration=300 --set run.trajectories=5 --out '" +
      (disk / "t").string() + "'");
  std::vector<std::string> left;
  std::error_code no_folder;  // the run folder may not exist at all
  for (const auto& entry : fs::directory_iterator(disk / "t", no_folder))
    left.push_back(entry.path().filename().string());
  std::system(("umount '" + disk.string() + "'").c_str());
  EXPECT_EQ(o.exit_code, 1) << o.output;
  EXPECT_THAT(o.output, HasSubstr("disk full?"));
  EXPECT_TRUE(left.empty()) << "left behind: " << ::testing::PrintToString(left);
}

}  // namespace
}  // namespace swarmagg
