// Output paths are checked before any work: a bad --out, --render-dir or --video ends a run
// of a long world at once, with exit 2 and a message naming the option, the path and the
// reason, before the first step.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_testing.hpp"
#include "plot/gnuplot.hpp"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

using Outcome = swarmagg::testing::CliOutcome;

Outcome swarmagg(const std::string& arguments) {
  return swarmagg::testing::run_swarmagg(arguments);
}

// A world far too long to finish while the test waits (10^8 steps): only a check made
// before the first step lets the command return.
const std::string kLongRun =
    "run worlds/examples/demo.yaml --replicates 1 --set run.duration=1e7 --quiet ";

class OutputPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("swarmagg-outputs-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "afile") << "not a folder\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

void expect_refused(const Outcome& o, const std::string& option, const std::string& why) {
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_THAT(o.output, HasSubstr(option));
  EXPECT_THAT(o.output, HasSubstr(why));
  EXPECT_THAT(o.output, Not(HasSubstr("filesystem error")));
  EXPECT_THAT(o.output, Not(HasSubstr("trajectories.h5")));
}

TEST_F(OutputPaths, AFileAsOutIsRefusedBeforeTheFirstStep) {
  const fs::path frames = dir_ / "frames";
  const Outcome o = swarmagg(kLongRun + "--render-every 1 --render-dir " + frames.string() +
                             " --out " + (dir_ / "afile").string());
  expect_refused(o, "--out " + (dir_ / "afile").string(), "is a file, not a folder");
  // A frame is drawn at the setup of the replicate: none means nothing was simulated.
  EXPECT_FALSE(fs::exists(frames / "frame_000000.png"));
}

// A folder where the run writes a file (or a file where it writes a folder) would fail the
// run once simulated, with --force too: refused before the first step.
TEST_F(OutputPaths, AnOutputPathTakenByAnotherKindIsRefusedBeforeTheFirstStep) {
  for (const auto& [name, folder] :
       {std::pair{"summary.json", true}, std::pair{"trajectories.h5", true},
        std::pair{"model-timeseries", false}}) {
    const fs::path out = dir_ / ("taken-" + std::string(name));
    fs::create_directories(out);
    if (folder) {
      fs::create_directories(out / name);
    } else {
      std::ofstream(out / name) << "a file\n";
    }
    const Outcome o = swarmagg(kLongRun + "--force --out " + out.string());
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_THAT(o.output, HasSubstr((out / name).string() + " is not a " +
                                    (folder ? "file" : "folder") + ", and the run writes one"));
  }
}

TEST_F(OutputPaths, AFolderThatCannotBeCreatedIsRefusedBeforeTheFirstStep) {
  const Outcome below_a_file = swarmagg(kLongRun + "--out " + (dir_ / "afile" / "run").string());
  expect_refused(below_a_file, "--out", "is a file, so no folder can be made below it");
  const Outcome in_proc = swarmagg(kLongRun + "--out /proc/swarmagg-nope");
  expect_refused(in_proc, "--out /proc/swarmagg-nope", "cannot create the folder");
}

TEST_F(OutputPaths, ABadVideoOrFrameFolderIsRefusedBeforeTheFirstStep) {
  const fs::path frames = dir_ / "frames";
  const Outcome video =
      swarmagg(kLongRun + "--out " + (dir_ / "run").string() + " --render-every 1 --render-dir " +
               frames.string() + " --video /proc/swarmagg-nope/x.mp4");
  expect_refused(video, "--video /proc/swarmagg-nope/x.mp4", "its folder /proc/swarmagg-nope");
  EXPECT_FALSE(fs::exists(frames / "frame_000000.png"));
  EXPECT_FALSE(fs::exists(dir_ / "run" / "timeseries.csv"));
  const Outcome render_dir =
      swarmagg(kLongRun + "--out " + (dir_ / "run").string() + " --render-every 1 --render-dir " +
               (dir_ / "afile").string());
  expect_refused(render_dir, "--render-dir", "is a file, not a folder");
}

TEST_F(OutputPaths, EveryCommandChecksItsOutputFolderFirst) {
  const std::string afile = (dir_ / "afile").string();
  for (const std::string& command :
       {"rates worlds/examples/demo.yaml --set run.duration=1e7 --quiet --out " + afile,
        "model worlds/examples/demo.yaml --quiet --out " + afile,
        "compare worlds/examples/demo.yaml --set run.duration=1e7 --quiet --out " + afile,
        "sweep examples/sweeps/p-leave-vs-count.yaml --quiet --out " + afile,
        "reproduce --quick --quiet --out " + afile}) {
    SCOPED_TRACE(command);
    expect_refused(swarmagg(command), "--out " + afile, "is a file, not a folder");
  }
}

// A second run into the folder of an earlier one is refused, before any work, until
// --force says to replace it.
TEST_F(OutputPaths, AnEarlierRunIsReplacedOnlyWithForce) {
  const fs::path out = dir_ / "run";
  const std::string tiny = "run worlds/examples/demo.yaml --replicates 1 --no-plots --quiet ";
  ASSERT_EQ(swarmagg(tiny + "--set run.duration=5 --out " + out.string()).exit_code, 0);
  const std::string earlier = swarmagg::testing::read_all(out / "world.resolved.yaml");
  const Outcome refused = swarmagg(kLongRun + "--out " + out.string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_THAT(refused.output, HasSubstr(out.string()));
  EXPECT_THAT(refused.output, HasSubstr("--force"));
  EXPECT_EQ(swarmagg::testing::read_all(out / "world.resolved.yaml"), earlier);
  const Outcome forced =
      swarmagg(tiny + "--set run.duration=6 --set robots.count=20 --force --out " + out.string());
  ASSERT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_THAT(swarmagg::testing::read_all(out / "world.resolved.yaml"), HasSubstr("count: 20"));
  // The summary names what the command line changed of the world file.
  EXPECT_THAT(swarmagg::testing::read_all(out / "summary.json"),
              HasSubstr("\"overrides\": [\n    \"run.duration=6\",\n    \"robots.count=20\",\n"
                        "    \"run.replicates=1\"\n  ]"));
}

// model and rates write beside a run by default; beside a run of another system their
// outputs would pass for that run's (its noa.png drawing a 10-agent model over 60 agents).
TEST_F(OutputPaths, ModelAndRatesRefuseARunOfAnotherWorldUnlessForced) {
  const fs::path out = dir_ / "run";
  ASSERT_EQ(swarmagg("run worlds/examples/demo.yaml --replicates 1 --no-plots --quiet "
                     "--set run.duration=5 --out " +
                     out.string())
                .exit_code,
            0);
  const std::string earlier = swarmagg::testing::read_all(out / "model.csv");
  for (const std::string command : {"model", "rates"}) {
    const Outcome refused = swarmagg(command + " worlds/examples/demo.yaml --set robots.count=10 " +
                                     "--set run.duration=5 --quiet --out " + out.string());
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_THAT(refused.output, HasSubstr("another world (robots.count: 60 there, 10 here)"));
    EXPECT_THAT(refused.output, HasSubstr("--force"));
  }
  EXPECT_EQ(swarmagg::testing::read_all(out / "model.csv"), earlier);
  EXPECT_FALSE(fs::exists(out / "rates.csv"));
  // The same system run longer or with other outputs is the same world.
  const Outcome longer = swarmagg(
      "model worlds/examples/demo.yaml --set run.duration=9 --quiet "
      "--set run.replicates=3 --out " +
      out.string());
  EXPECT_EQ(longer.exit_code, 0) << longer.output;
  const Outcome forced = swarmagg(
      "model worlds/examples/demo.yaml --set robots.count=10 --quiet "
      "--force --out " +
      out.string());
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
}

// `plot A --out B`, B another run's folder: B's plots would be A's, read as B's own.
TEST_F(OutputPaths, PlotRefusesToReplaceAnotherRunsPlotsUnlessForced) {
  const std::string run = "run worlds/examples/demo.yaml --replicates 1 --quiet --no-plots ";
  ASSERT_EQ(swarmagg(run + "--set run.duration=5 --out " + (dir_ / "a").string()).exit_code, 0);
  ASSERT_EQ(swarmagg(run + "--set run.duration=9 --out " + (dir_ / "b").string()).exit_code, 0);
  std::ofstream(dir_ / "b" / "noa.png") << "b's own plot\n";
  const std::string plot = "plot " + (dir_ / "a").string() + " --quiet ";
  expect_refused(swarmagg(plot + "--out " + (dir_ / "b").string()), "--out",
                 "holds a run (world.resolved.yaml)");
  EXPECT_EQ(swarmagg::testing::read_all(dir_ / "b" / "noa.png"), "b's own plot\n");
  EXPECT_FALSE(fs::exists(dir_ / "b" / "plots"));
  // A comparison's folder has a noa.png of its own, drawn from both engines.
  fs::create_directories(dir_ / "compared");
  std::ofstream(dir_ / "compared" / "compare.json") << "{}\n";
  std::ofstream(dir_ / "compared" / "noa.png") << "both engines\n";
  expect_refused(swarmagg(plot + "--out " + (dir_ / "compared").string()), "--out",
                 "holds a comparison (compare.json)");
  EXPECT_EQ(swarmagg::testing::read_all(dir_ / "compared" / "noa.png"), "both engines\n");
  if (swarmagg::gnuplot_available()) {
    EXPECT_EQ(swarmagg(plot + "--out " + (dir_ / "a").string()).exit_code, 0);  // its own
    EXPECT_EQ(swarmagg(plot + "--out " + (dir_ / "b").string() + " --force").exit_code, 0);
  }
}

// A folder `rates` wrote holds no run, but its rates.json says which world they were measured
// in: another world's rates are neither replaced nor joined by a model without --force.
TEST_F(OutputPaths, ModelAndRatesRefuseRatesOfAnotherWorldUnlessForced) {
  const fs::path out = dir_ / "rates";
  const std::string world = "worlds/examples/demo.yaml --set run.duration=5 --quiet ";
  ASSERT_EQ(swarmagg("rates " + world + "--replicates 1 --out " + out.string()).exit_code, 0);
  const std::string earlier = swarmagg::testing::read_all(out / "rates.csv");
  for (const std::string command : {"model", "rates"}) {
    const Outcome refused =
        swarmagg(command + " " + world + "--set robots.count=10 --out " + out.string());
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_THAT(refused.output,
                HasSubstr("holds rates of another world (robots.count: 60 there, 10 here)"));
    EXPECT_THAT(refused.output, HasSubstr("--force"));
  }
  EXPECT_EQ(swarmagg::testing::read_all(out / "rates.csv"), earlier);
  EXPECT_FALSE(fs::exists(out / "model.csv"));
  // The same system measured again is the same world; --force writes over another's.
  EXPECT_EQ(swarmagg("rates " + world + "--replicates 2 --out " + out.string()).exit_code, 0);
  EXPECT_EQ(swarmagg("model " + world + "--out " + out.string()).exit_code, 0);
  const Outcome forced =
      swarmagg("rates " + world + "--set robots.count=10 --force --out " + out.string());
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_NE(swarmagg::testing::read_all(out / "rates.csv"), earlier);
  // A rates.json that cannot be read cannot tell whose rates they are.
  std::ofstream(out / "rates.json") << "{{{ damaged";
  const Outcome unreadable = swarmagg("rates " + world + "--out " + out.string());
  EXPECT_EQ(unreadable.exit_code, 2) << unreadable.output;
  EXPECT_THAT(unreadable.output, HasSubstr("rates.json cannot be read"));
}

TEST_F(OutputPaths, AModelLeavesNoVariantOfAnEarlierModelBehind) {
  const fs::path rates = dir_ / "rates";
  const fs::path out = dir_ / "model";
  const std::string world = "worlds/examples/demo.yaml --set run.duration=20 --quiet ";
  ASSERT_EQ(swarmagg("rates " + world + "--replicates 2 --out " + rates.string()).exit_code, 0);
  ASSERT_EQ(swarmagg("model " + world + "--rates " + (rates / "rates.csv").string() + " --out " +
                     out.string())
                .exit_code,
            0);
  ASSERT_TRUE(fs::exists(out / "model-timeseries" / "bayindir-measured.csv"));
  std::ofstream(out / "model-timeseries" / "bayindir-mine.csv") << "yours\n";
  ASSERT_EQ(swarmagg("model " + world + "--out " + out.string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "model-timeseries" / "bayindir-measured.csv"));
  EXPECT_TRUE(fs::exists(out / "model-timeseries" / "bayindir-original.csv"));
  EXPECT_TRUE(fs::exists(out / "model-timeseries" / "bayindir-mine.csv"));  // not a model's
}

TEST_F(OutputPaths, RatesOfAnotherWorldAreFedToAModelWithAWarning) {
  const fs::path rates = dir_ / "rates";
  ASSERT_EQ(swarmagg("rates worlds/examples/demo.yaml --set run.duration=20 --quiet --set "
                     "robots.count=30 --replicates 2 --out " +
                     rates.string())
                .exit_code,
            0);
  const std::string feed = " --rates " + (rates / "rates.csv").string() + " --quiet --out ";
  const Outcome other = swarmagg("model worlds/examples/demo.yaml" + feed + (dir_ / "a").string());
  EXPECT_EQ(other.exit_code, 0) << other.output;
  EXPECT_THAT(other.output,
              HasSubstr("it was measured in another world (robots.count: 30 there, 60 here)"));
  const Outcome same = swarmagg("model worlds/examples/demo.yaml --set robots.count=30" + feed +
                                (dir_ / "b").string());
  EXPECT_EQ(same.exit_code, 0) << same.output;
  EXPECT_THAT(same.output, Not(HasSubstr("another world")));
  // Without a rates.json to tell the world, the rows still tell the model they were written for.
  const fs::path soysal = dir_ / "soysal";
  ASSERT_EQ(swarmagg("rates worlds/paper/soysal-5-constant.yaml --set run.duration=200 --quiet "
                     "--replicates 1 --out " +
                     soysal.string())
                .exit_code,
            0);
  std::ofstream(soysal / "rates.json") << "{{{ damaged";
  const Outcome crossed =
      swarmagg("model worlds/examples/demo.yaml --rates " + (soysal / "rates.csv").string() +
               " --quiet --out " + (dir_ / "c").string());
  EXPECT_EQ(crossed.exit_code, 0) << crossed.output;
  EXPECT_THAT(crossed.output, HasSubstr("rates.json beside it cannot be read"));
  EXPECT_THAT(crossed.output, HasSubstr("its rows were written for the soysal model, this "
                                        "world's is the bayindir model"));
  // A rates.csv copied alone cannot be checked against the world: that is said too.
  fs::remove(rates / "rates.json");
  const Outcome alone = swarmagg("model worlds/examples/demo.yaml" + feed + (dir_ / "d").string());
  EXPECT_EQ(alone.exit_code, 0) << alone.output;
  EXPECT_THAT(alone.output, HasSubstr("no rates.json beside it records the world"));
}

// A run killed outright leaves hidden temporaries wherever it was writing; --force clears
// them (those of no living process) from every folder a run writes into.
TEST_F(OutputPaths, ForceRemovesAKilledRunsTemporariesFromEveryFolderItWrites) {
  const fs::path out = dir_ / "run";
  const std::string tiny =
      "run worlds/examples/demo.yaml --replicates 1 --no-plots --quiet "
      "--set run.duration=5 --out " +
      out.string();
  ASSERT_EQ(swarmagg(tiny).exit_code, 0);
  // Process 999999998 lies above any pid_max: nobody is writing these.
  const std::vector<fs::path> left = {
      out / ".summary.json.999999998.0.tmp", out / "plots" / ".noa.png.999999998.1.tmp",
      out / "model-timeseries" / ".bayindir-original.csv.999999998.2.tmp",
      out / "frames" / ".frame_000010.png.999999998.3.tmp"};
  for (const fs::path& file : left) {
    fs::create_directories(file.parent_path());
    std::ofstream(file) << "partial";
  }
  const fs::path someone_elses =
      out / "frames" / (".frame_000020.png." + std::to_string(::getpid()) + ".0.tmp");
  std::ofstream(someone_elses) << "being written";
  ASSERT_EQ(swarmagg(tiny + " --force").exit_code, 0);
  for (const fs::path& file : left) EXPECT_FALSE(fs::exists(file)) << file;
  EXPECT_TRUE(fs::exists(someone_elses));  // a living process's
}

// Another model's plots go even when the earlier rates.csv that listed them is gone.
TEST_F(OutputPaths, RatesLeaveNoEarlierRatePlotBehind) {
  const fs::path out = dir_ / "rates";
  fs::create_directories(out);
  for (const char* file : {"rates-pairup.png", "rates-pairup.gp", "rates-join.csv"})
    std::ofstream(out / file) << "an earlier Soysal world's";
  std::ofstream(out / "rates.csv") << "damaged\n";
  std::ofstream(out / "rates-mine.txt") << "yours";
  ASSERT_EQ(swarmagg("rates worlds/examples/demo.yaml --set run.duration=20 --replicates 1 "
                     "--quiet --out " +
                     out.string())
                .exit_code,
            0);
  for (const char* file : {"rates-pairup.png", "rates-pairup.gp", "rates-join.csv"})
    EXPECT_FALSE(fs::exists(out / file)) << file;
  EXPECT_TRUE(fs::exists(out / "rates-mine.txt"));
  EXPECT_TRUE(fs::exists(out / "rates.csv"));
}

}  // namespace
