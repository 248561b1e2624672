// Runs the built `swarmagg` binary as a user would and checks exit codes and messages.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_testing.hpp"
#include "config/world_loader.hpp"

namespace {

using ::testing::HasSubstr;

using Outcome = swarmagg::testing::CliOutcome;

Outcome swarmagg(const std::string& arguments, const std::string& environment = "") {
  return swarmagg::testing::run_swarmagg(arguments, environment);
}

// The same, with environment assignments (e.g. "PATH=/x") for the child only.
Outcome swarmagg_with_env(const std::string& environment, const std::string& arguments) {
  return swarmagg(arguments, environment);
}

// Named by the process too: suites of several checkouts may run at once on one machine.
std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("swarmagg-cli-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  return dir;
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Cli, HelpWorksForEverySubcommand) {
  EXPECT_EQ(swarmagg("--help").exit_code, 0);
  for (const char* sub : {"run", "validate"}) {
    const Outcome o = swarmagg(std::string(sub) + " --help");
    EXPECT_EQ(o.exit_code, 0) << sub;
    EXPECT_THAT(o.output, HasSubstr("--set")) << sub;
    const Outcome via_help = swarmagg(std::string("help ") + sub);
    EXPECT_EQ(via_help.exit_code, 0) << sub;
    EXPECT_EQ(via_help.output, o.output) << sub;
  }
  EXPECT_EQ(swarmagg("help nope").exit_code, 2);
  EXPECT_EQ(swarmagg("help run --markdown").exit_code, 2);
}

TEST(Cli, ValidatePrintsTheResolvedWorldWithOverrides) {
  const Outcome o = swarmagg("validate worlds/paper/creation-150.yaml --set robots.count=80");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("count: 80"));
  EXPECT_THAT(o.output, HasSubstr("isolated_wait: resume"));
}

// A duration between two whole steps runs the nearer one (a sweep over engine.dt keeps one
// duration), and says so: summary.json records the duration asked for.
TEST(Cli, ADurationOfNoWholeNumberOfStepsSaysWhatRuns) {
  const Outcome between = swarmagg("validate worlds/examples/demo.yaml --set run.duration=20.06");
  EXPECT_EQ(between.exit_code, 0) << between.output;
  EXPECT_THAT(between.output,
              HasSubstr("note: run.duration 20.06 is 200.6 steps of engine.dt 0.1: each "
                        "replicate runs the nearest whole number, 201, 20.1 tu"));
  const Outcome whole = swarmagg("validate worlds/examples/demo.yaml --set run.duration=0.3");
  EXPECT_THAT(whole.output, ::testing::Not(HasSubstr("note:")))
      << "0.3 / 0.1 rounds to 2.9999999999999996, a whole step";
}

// CLI11 alone read `--replicates 010` as 8 and `0x10` as 16; a world file reads 010 as 10.
TEST(Cli, IntegerOptionsAreDecimal) {
  const Outcome leading_zeros =
      swarmagg("validate worlds/examples/demo.yaml --replicates 010 --seed 007");
  ASSERT_EQ(leading_zeros.exit_code, 0) << leading_zeros.output;
  EXPECT_THAT(leading_zeros.output, HasSubstr("replicates: 10\n"));
  EXPECT_THAT(leading_zeros.output, HasSubstr("seed: 7\n"));
  for (const char* arguments :
       {"validate worlds/examples/demo.yaml --replicates 0x10",
        "validate worlds/examples/demo.yaml --threads 1e1",
        "run worlds/examples/demo.yaml --render-every 0b11 --out /tmp/swarmagg-never-written",
        "sweep worlds/examples/demo.yaml --threads 0x2 --list",
        "validate worlds/examples/demo.yaml --replicates +5",
        "reproduce --plot-width 0x300 --worlds /nonexistent-paper-worlds"}) {
    const Outcome o = swarmagg(arguments);
    EXPECT_EQ(o.exit_code, 2) << arguments << "\n" << o.output;
    EXPECT_THAT(o.output, HasSubstr("expected a whole number in decimal digits")) << arguments;
  }
}

// A world printed onto a full disk is not a success.
TEST(Cli, OutputThatCannotBeWrittenIsAFailure) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  for (const char* command :
       {"validate worlds/examples/demo.yaml", "keys", "--help", "run --help", "--version"}) {
    const Outcome o = swarmagg::testing::run_swarmagg(command, "", "/dev/full");
    EXPECT_EQ(o.exit_code, 1) << command;
    EXPECT_THAT(o.output, HasSubstr("cannot write to standard output")) << command;
  }
}

// A world the models refuse keeps its run: the run notes why model.csv is missing, and `model`
// refuses at once, before any placement is drawn.
TEST(Cli, AWorldTheModelsRefuseStillRunsAndModelRefusesIt) {
  const std::string world = "worlds/paper/soysal-5-constant.yaml --set robots.count=40 ";
  const std::string out = ::testing::TempDir() + "swarmagg-refused-model";
  const Outcome ran = swarmagg::testing::run_swarmagg(
      "run " + world + "--set run.duration=1 --replicates 1 --no-plots --force --out " + out);
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
  EXPECT_THAT(ran.output, HasSubstr("note: no model.csv: model: the partition model of 40 agents"));
  const Outcome model =
      swarmagg::testing::run_swarmagg("model " + world + "--out " + out + "-model");
  EXPECT_EQ(model.exit_code, 2) << model.output;
  EXPECT_THAT(model.output, HasSubstr("the partition model of 40 agents"));
  std::filesystem::remove_all(out);
}

// A nearly full walled arena: the run's replicate placed its agents, but one of the models'
// thousands of sampled placements jams. The run keeps its outputs and notes the model's
// absence (it exited 2 after simulating, with the placement's words only).
TEST(Cli, AModelStartThatCannotBePlacedKeepsTheRun) {
  const std::string out = ::testing::TempDir() + "swarmagg-jammed-start";
  const Outcome ran = swarmagg::testing::run_swarmagg(
      "run worlds/paper/full-0.0025.yaml --set arena.topology=walls --set arena.width=100 "
      "--set arena.height=10.01 --set robots.count=150 --set run.duration=1 --replicates 1 "
      "--no-plots --force --out " +
      out);
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
  EXPECT_THAT(ran.output, HasSubstr("note: no model.csv: the models' start"));
  EXPECT_THAT(ran.output, HasSubstr("placement_second_order"));
  EXPECT_TRUE(std::filesystem::exists(out + "/timeseries.csv"));
  EXPECT_FALSE(std::filesystem::exists(out + "/model.csv"));
  std::filesystem::remove_all(out);
}

// A run's model errors compare with models that assume a torus: a walled world says so, as
// `model` does.
TEST(Cli, AWalledRunNotesThatTheModelsHaveNoWalls) {
  const std::string out = ::testing::TempDir() + "swarmagg-walled";
  const std::string walled =
      "worlds/examples/demo.yaml --set run.duration=5 --replicates 1 --force --out " + out;
  const Outcome ran =
      swarmagg::testing::run_swarmagg("run " + walled + " --no-plots --set arena.topology=walls");
  EXPECT_EQ(ran.exit_code, 0) << ran.output;
  EXPECT_THAT(ran.output, HasSubstr("note: the models assume agents spread uniformly over the "
                                    "arena area; walls are not modelled"));
  const Outcome torus = swarmagg::testing::run_swarmagg("run " + walled + " --no-plots");
  EXPECT_THAT(torus.output, ::testing::Not(HasSubstr("walls are not modelled")));
  std::filesystem::remove_all(out);
}

TEST(Cli, BadInputExitsTwoWithTheFileAndKey) {
  // A rates.csv with its header and no rows measured nothing: a `measured` variant from it
  // would be the world's own model under another name.
  const std::filesystem::path header_only = temp_dir("header-only-rates") / "rates.csv";
  std::filesystem::create_directories(header_only.parent_path());
  std::ofstream(header_only) << "term,size,events,exposure,rate,ci_low,ci_high,model,variant,"
                                "model_rate\n";
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"run /nonexistent.yaml", "/nonexistent.yaml"},
      {"validate worlds/examples/demo.yaml --set robots.radius=-2", "robots.radius"},
      {"run", "swarmagg run: world is required (swarmagg run --help lists the options)"},
      {"run worlds/examples/demo.yaml --bogus",
       "swarmagg run: The following argument was not expected: --bogus"},
      {"rnu worlds/examples/demo.yaml", "unknown command 'rnu'; did you mean 'run'?"},
      {"frobnicate", "unknown command 'frobnicate'"},
      {"run worlds/examples/demo.yaml --out ''", "--out: expected a path, got ''"},
      {"validate worlds/examples/demo.yaml --set robots=5",
       "--set: 'robots' is a block of keys: set one of them, e.g. robots."},
      {"model worlds/examples/demo.yaml --rates worlds --out " + temp_dir("model-rates").string(),
       "worlds: is a folder; expected the rates.csv of `swarmagg rates` or `run --rates`"},
      {"model worlds/examples/demo.yaml --rates " + header_only.string() + " --out " +
           temp_dir("model-header-only").string(),
       "rates.csv: holds a header but no rows; expected the terms a run measured"},
      {"video /nonexistent-frames v.mp4", "/nonexistent-frames: no such folder"},
      // Frame and video options a run would not use: the frames or video expected would not
      // come.
      {"run worlds/examples/demo.yaml --render-size 100x100", "--render-size needs frames"},
      {"run worlds/examples/demo.yaml --render-dir x", "--render-dir needs frames"},
      {"run worlds/examples/demo.yaml --fps 30", "--fps needs --video"},
      {"run worlds/examples/demo.yaml --set robots.count=5 --set robots.count=20",
       "--set robots.count is given twice: give it once"},
      {"reproduce --quick --set run.seed=1 --set run.seed=2",
       "--set run.seed is given twice: give it once"},
      {"render /nonexistent-run --fps -5", "--fps needs --video"},
      {"run worlds/examples/demo.yaml --video ''", "--video: expected a path, got ''"},
      {"validate worlds", "worlds: is a folder; expected a world file"},
      {"plot /nonexistent-run", "/nonexistent-run: no such folder"},
      {"reproduce --quick --only soysal-10 --timeout-duration 100",
       "--timeout-duration: the leave-timeout series is not selected"},
      // Each arm sets its engine: a --set of it would be recorded against the other arm.
      {"compare worlds/examples/demo.yaml --set engine.type=box2d",
       "--set engine.type: compare runs the world on both engines"},
      // Both would set run.seed; one of them would be silently unused.
      {"run worlds/examples/demo.yaml --seed 5 --set run.seed=6",
       "--seed and --set run.seed both set run.seed: give one of them"},
      {"run worlds/examples/demo.yaml --render-every 5 --set render.every=10",
       "--render-every and --set render.every both set render.every: give one of them"},
      {"run worlds/examples/demo.yaml --render-every 5 --render-size 80x60 --set render.height=9",
       "--render-size and --set render.height both set render.height"},
      {"run worlds/examples/demo.yaml --trajectories 5 --set run.trajectories=10",
       "--trajectories and --set run.trajectories both set run.trajectories"},
      {"reproduce --quick --worlds /nonexistent-worlds",
       "--worlds: /nonexistent-worlds: no such folder (expected the paper's worlds)"},
      // A reproduction of no world would be an empty report that reads as a success.
      {"reproduce --quick --only no-such-world --out " + temp_dir("reproduce-none").string(),
       "--only: no paper world's name contains 'no-such-world'"},
      // validate checks what the engine refuses at its start, as run does.
      {"validate worlds/examples/cockroach.yaml --engine box2d --set robots.detection_radius=49",
       "a torus arena must be wider and higher than 100.2 for the Box2D engine"},
      // Another controller ran, then failed on the model files it has none of.
      {"reproduce --quick --only full-0.0025 --set controller.type=cockroach --out " +
           temp_dir("reproduce-other").string(),
       "--set controller.type: reproduce runs the paper's experiments with their own"},
  };
  for (const auto& [arguments, message] : refused) {
    const Outcome o = swarmagg(arguments);
    EXPECT_EQ(o.exit_code, 2) << arguments << ": " << o.output;
    EXPECT_THAT(o.output, HasSubstr(message)) << arguments;
  }
}

// --force replaces the earlier run whole: its model, rates and plots do not stay beside a run
// that writes none of them (its plots drew the old model against the new run).
TEST(Cli, ForceLeavesNothingOfTheEarlierRun) {
  const std::filesystem::path out = temp_dir("force");
  const std::string run =
      "run worlds/examples/demo.yaml --set run.duration=30 --replicates 2 "
      "--quiet --no-plots --out " +
      out.string();
  ASSERT_EQ(swarmagg(run + " --rates").exit_code, 0);
  for (const char* name : {"model.csv", "rates.csv", "rates-escape.gp", "model-timeseries"})
    ASSERT_TRUE(std::filesystem::exists(out / name)) << name;
  std::ofstream(out / "notes.txt") << "mine\n";
  std::ofstream(out / "rates-notes.csv") << "mine\n";  // not one of the run's rate terms
  const Outcome again = swarmagg(run + " --force --no-model --set robots.count=10");
  ASSERT_EQ(again.exit_code, 0) << again.output;
  for (const char* name : {"model.csv", "rates.csv", "rates.json", "rates-escape.gp",
                           "rates-escape.csv", "model-timeseries"})
    EXPECT_FALSE(std::filesystem::exists(out / name)) << name;
  for (const char* name :
       {"world.resolved.yaml", "timeseries.csv", "summary.json", "notes.txt", "rates-notes.csv"})
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  std::filesystem::remove_all(out);
}

// A controller no macroscopic model describes: model.csv is the bare header, with no empty
// model-timeseries/ beside it, and `run` says why as `model` does.
TEST(Cli, AControllerWithoutAModelGetsAHeaderOnlyModelCsvAndANote) {
  const std::filesystem::path out = temp_dir("no-model");
  const Outcome o = swarmagg(
      "run worlds/examples/cockroach.yaml --set run.duration=30 "
      "--replicates 1 --no-plots --out " +
      out.string());
  ASSERT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("note: no macroscopic model describes controller type "
                                  "'cockroach' (docs/models.md): model.csv holds its header only"));
  std::ifstream model(out / "model.csv");
  const std::string text((std::istreambuf_iterator<char>(model)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "model,variant,step,time,quantity,value\n");
  EXPECT_FALSE(std::filesystem::exists(out / "model-timeseries"));
  std::filesystem::remove_all(out);
  // `model` into a folder an earlier model wrote: its variant files go, and their folder too.
  const std::filesystem::path models = temp_dir("no-model-after-a-model");
  const std::string into = " --quiet --out " + models.string();
  ASSERT_EQ(swarmagg("model worlds/examples/demo.yaml" + into).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(models / "model-timeseries"));
  const Outcome again = swarmagg("model worlds/examples/cockroach.yaml" + into);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_FALSE(std::filesystem::exists(models / "model-timeseries"));
  std::filesystem::remove_all(models);
}

// A folder `rates` wrote holds the rates of another run: `run --force` without --rates leaves
// no rates.csv there that a later `model --rates` (or the Ctrl-C note) would take for its own.
TEST(Cli, ForceLeavesNoRatesOfAnEarlierRatesCommand) {
  const std::filesystem::path out = temp_dir("force-rates");
  const std::string world = "worlds/examples/demo.yaml --set run.duration=30 --quiet ";
  ASSERT_EQ(swarmagg("rates " + world + "--replicates 2 --out " + out.string()).exit_code, 0);
  ASSERT_TRUE(std::filesystem::exists(out / "rates.json"));
  const Outcome run =
      swarmagg("run " + world + "--no-plots --no-model --force --out " + out.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* name : {"rates.csv", "rates.json", "rates-escape.gp"})
    EXPECT_FALSE(std::filesystem::exists(out / name)) << name;
  EXPECT_TRUE(std::filesystem::exists(out / "world.resolved.yaml"));
  std::filesystem::remove_all(out);
  // A rates.json that `rates` did not write marks no rates folder: the user's files stay.
  std::filesystem::create_directories(out / "plots");
  std::ofstream(out / "rates.json") << "{\"mine\": 1}\n";
  std::ofstream(out / "plots" / "my-figure.png") << "mine\n";
  std::ofstream(out / "model.csv") << "mine\n";
  ASSERT_EQ(
      swarmagg("run " + world + "--no-plots --no-model --force --out " + out.string()).exit_code,
      0);
  for (const char* name : {"rates.json", "plots/my-figure.png", "model.csv"})
    EXPECT_TRUE(std::filesystem::exists(out / name)) << name;
  std::filesystem::remove_all(out);
}

// A sweep merges itself; what that merge removes of an earlier one (here a stale
// sweep_partitions.csv: the demo's controller records no partitions) is named, as `merge` names
// it, with or without the sweep's plots.
TEST(Cli, ASweepNamesWhatItsMergeRemoved) {
  const std::filesystem::path out = temp_dir("sweep-removed");
  const std::filesystem::path file = out.string() + ".yaml";
  std::ofstream(file) << "name: small\nbase: " SWARMAGG_SOURCE_DIR
                         "/worlds/examples/demo.yaml\nparameters:\n"
                         "  controller.p_leave: [0.001, 0.01]\n  run.duration: [15]\n"
                         "replicates: 1\nseed: 11\n";
  const std::string sweep = "sweep " + file.string() + " --no-plots --out " + out.string();
  const Outcome first = swarmagg(sweep);
  ASSERT_EQ(first.exit_code, 0) << first.output;
  std::ofstream(out / "sweep_partitions.csv") << "earlier\n";
  const Outcome again = swarmagg(sweep);
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_THAT(again.output,
              HasSubstr("this one outdates: " + (out / "sweep_partitions.csv").string()));
  EXPECT_FALSE(std::filesystem::exists(out / "sweep_partitions.csv"));
  std::filesystem::remove_all(out);
  std::filesystem::remove(file);
}

// Each arm of a comparison is a run folder: its summary.json names what the command line
// changed, as `run`'s does, and a run the comparison replaces (--force) leaves none of its
// files, its trajectories included.
TEST(Cli, CompareArmsNameTheirOverridesAndReplaceARunWhole) {
  const std::filesystem::path out = temp_dir("compare-arms");
  const std::string world = "worlds/examples/demo.yaml --set run.duration=20 --quiet ";
  ASSERT_EQ(
      swarmagg("run " + world + "--replicates 2 --no-plots --trajectories 10 --out " + out.string())
          .exit_code,
      0);
  ASSERT_TRUE(std::filesystem::exists(out / "trajectories.h5"));
  const Outcome compare =
      swarmagg("compare " + world + "--replicates 2 --seed 9 --set robots.count=30 --force --out " +
               out.string());
  ASSERT_EQ(compare.exit_code, 0) << compare.output;
  EXPECT_FALSE(std::filesystem::exists(out / "trajectories.h5"));
  EXPECT_FALSE(std::filesystem::exists(out / "world.resolved.yaml"));
  std::ifstream in(out / "box2d" / "summary.json");
  const nlohmann::json overrides = nlohmann::json::parse(in).at("overrides");
  EXPECT_EQ(overrides, nlohmann::json({"run.duration=20", "robots.count=30", "run.replicates=2",
                                       "run.seed=9", "engine.type=box2d"}));
  std::filesystem::remove_all(out);
}

// summary.json's model errors describe the model beside the run: `model` into a run's folder
// writes them, whether the run had no model (--no-model, or Ctrl-C while it was computed) or
// another one (with measured variants this one lacks).
TEST(Cli, ModelIntoARunFolderUpdatesItsModelErrors) {
  const std::filesystem::path out = temp_dir("model-errors");
  const auto variants = [&out] {
    std::ifstream in(out / "summary.json");
    std::vector<std::string> names;
    const nlohmann::json errors = nlohmann::json::parse(in).value("model_errors", nlohmann::json());
    if (errors.is_array())
      for (const auto& e : errors) names.push_back(e.at("variant").get<std::string>());
    return names;
  };
  const std::string world =
      "worlds/examples/demo.yaml --set run.duration=30 --set run.replicates=2 --quiet ";
  ASSERT_EQ(
      swarmagg("run " + world + "--no-plots --rates --no-model --out " + out.string()).exit_code,
      0);
  EXPECT_THAT(variants(), ::testing::IsEmpty());
  ASSERT_EQ(swarmagg("model " + world + "--rates " + (out / "rates.csv").string() + " --out " +
                     out.string())
                .exit_code,
            0);
  EXPECT_THAT(variants(), ::testing::Contains("measured"));
  const Outcome without_rates = swarmagg("model " + world + "--out " + out.string());
  ASSERT_EQ(without_rates.exit_code, 0) << without_rates.output;
  EXPECT_THAT(variants(), ::testing::ElementsAre("collision", "original", "returns"));
  // A model of another run (its noise floors batches of 4 replicates, the run's of 2) leaves
  // the run no errors, rather than errors beside floors of another run.
  const Outcome other =
      swarmagg("model worlds/examples/demo.yaml --set run.duration=30 --progress never --out " +
               out.string());
  ASSERT_EQ(other.exit_code, 0) << other.output;
  EXPECT_THAT(other.output, HasSubstr("is another run (run.replicates: 2 there, 4 here)"));
  EXPECT_THAT(variants(), ::testing::IsEmpty());
  // --quiet keeps the notes on outputs left out.
  const Outcome quiet = swarmagg(
      "model worlds/examples/demo.yaml --set run.duration=30 --quiet "
      "--out " +
      out.string());
  EXPECT_THAT(quiet.output, HasSubstr("note: the run in " + out.string() + "/ is another run"));
  // Errors the model cannot be compared with (the run's time series cut short) do not leave
  // the earlier model's errors in their place.
  ASSERT_EQ(swarmagg("model " + world + "--out " + out.string()).exit_code, 0);
  ASSERT_THAT(variants(), ::testing::Not(::testing::IsEmpty()));
  const std::string series = file_text(out / "timeseries.csv");
  std::ofstream(out / "timeseries.csv", std::ios::trunc) << series.substr(0, series.size() / 2);
  const Outcome cut = swarmagg("model " + world + "--set model.kappa=paper --out " + out.string());
  EXPECT_EQ(cut.exit_code, 0) << cut.output;
  EXPECT_THAT(cut.output, HasSubstr("warning: the model is written, but not its errors"));
  EXPECT_THAT(variants(), ::testing::IsEmpty());
  std::filesystem::remove_all(out);
}

// compare, as run, replaces what its folder holds only with --force, and then its arms whole.
TEST(Cli, CompareReplacesAnEarlierFolderOnlyWithForce) {
  const auto out = temp_dir("compare-force");
  // A run's folder with a stale arm file in it: the run's outputs and the arm go, yours stay.
  ASSERT_EQ(
      swarmagg("run worlds/examples/demo.yaml --set run.duration=5 --quiet --no-plots --out " +
               out.string())
          .exit_code,
      0);
  std::filesystem::create_directories(out / "kinematic");
  std::ofstream(out / "kinematic" / "trajectories.h5") << "an earlier arm's";
  std::ofstream(out / "notes.txt") << "mine";
  const std::string compare =
      "compare worlds/examples/demo.yaml --set run.duration=20 --replicates 2 --quiet --out " +
      out.string();
  const Outcome refused = swarmagg(compare);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_THAT(refused.output, HasSubstr("already holds files"));
  EXPECT_TRUE(std::filesystem::exists(out / "kinematic" / "trajectories.h5"));
  const Outcome forced = swarmagg(compare + " --force");
  EXPECT_EQ(forced.exit_code, 0) << forced.output;
  EXPECT_TRUE(std::filesystem::exists(out / "compare.json"));
  EXPECT_FALSE(std::filesystem::exists(out / "kinematic" / "trajectories.h5"));
  EXPECT_FALSE(std::filesystem::exists(out / "timeseries.csv")) << "the run's outputs stayed";
  EXPECT_FALSE(std::filesystem::exists(out / "world.resolved.yaml"));
  EXPECT_TRUE(std::filesystem::exists(out / "notes.txt"));
  std::filesystem::remove_all(out);
}

// A video the run could not make is refused before the simulation, not after it.
TEST(Cli, ABadVideoRequestIsRefusedBeforeTheRun) {
  const std::filesystem::path dir = temp_dir("video");
  const std::string out = (dir / "run").string();
  const std::string run =
      "run worlds/paper/full-0.0025.yaml --set run.duration=50 --render-every 100 --out " + out;
  const Outcome fps = swarmagg(run + " --video " + out + ".mp4 --fps 0");
  EXPECT_EQ(fps.exit_code, 2) << fps.output;
  EXPECT_THAT(fps.output, HasSubstr("video frame rate 0"));
  const Outcome name = swarmagg(run + " --video " + out + "-without-extension");
  EXPECT_EQ(name.exit_code, 2) << name.output;
  EXPECT_THAT(name.output, HasSubstr("needs a file name with an extension"));
  EXPECT_FALSE(std::filesystem::exists(out));
  std::filesystem::remove_all(dir);
}

// --seed is checked as run.seed is: every 64-bit value and nothing else (it was wrapped from
// -1 and clamped from 2^64 to 2^64 - 1 without a word).
TEST(Cli, SeedsOutside64BitsAreRefused) {
  for (const char* seed : {"18446744073709551616"}) {
    const Outcome o = swarmagg(std::string("validate worlds/examples/demo.yaml --seed ") + seed);
    EXPECT_EQ(o.exit_code, 2) << seed;
    EXPECT_THAT(o.output, HasSubstr("--seed: run.seed")) << seed;
  }
  for (const char* seed : {"1e3", "-1"}) {
    const Outcome o = swarmagg(std::string("validate worlds/examples/demo.yaml --seed ") + seed);
    EXPECT_EQ(o.exit_code, 2) << seed;
    EXPECT_THAT(o.output, HasSubstr(std::string("--seed: expected a whole number in decimal "
                                                "digits, got '") +
                                    seed + "'"));
  }
  const Outcome largest =
      swarmagg("validate worlds/examples/demo.yaml --seed 18446744073709551615");
  EXPECT_EQ(largest.exit_code, 0) << largest.output;
  EXPECT_THAT(largest.output, HasSubstr("seed: 18446744073709551615"));
}

TEST(Cli, RunWritesTheOutputFolder) {
  const auto out = temp_dir("run");
  const Outcome o = swarmagg(
      "run worlds/examples/demo.yaml --replicates 2 --threads 2 "
      "--set run.duration=50 --out " +
      out.string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(o.output, HasSubstr("mean final NOA"));
  EXPECT_TRUE(std::filesystem::exists(out / "timeseries.csv"));
  EXPECT_TRUE(std::filesystem::exists(out / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(out / "world.resolved.yaml"));
  std::filesystem::remove_all(out);
}

// --render-dir reaches render.dir as the typed string it is: a name holding `"` and `\` once
// came out as YAML escapes (the option was spliced into a `--set` text).
TEST(Cli, RenderDirKeepsQuotesAndBackslashes) {
  const auto out = temp_dir("render-dir");
  const std::filesystem::path frames = out / "fr\"am\\es";
  const Outcome o = swarmagg(
      "run worlds/examples/demo.yaml --replicates 1 --set run.duration=0.3 --no-model --quiet "
      "--render-every 1 --render-size 64x64 --out '" +
      out.string() + "' --render-dir '" + frames.string() + "'");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(std::filesystem::exists(frames / "frame_000000.png")) << o.output;
  EXPECT_EQ(swarmagg::load_world((out / "world.resolved.yaml").string()).render.dir,
            frames.string());
  std::filesystem::remove_all(out);
}

int occurrences(const std::string& text, const std::string& part) {
  int count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

constexpr const char* kTinyRun =
    "run worlds/examples/demo.yaml --replicates 2 --set run.duration=30 --set robots.count=20 ";

TEST(Cli, ARunWithoutGnuplotSucceedsAndSaysOnceThatPlotsWereSkipped) {
  const auto out = temp_dir("no-gnuplot");
  // The child's PATH holds no gnuplot (the binary is named by its absolute path).
  const Outcome o =
      swarmagg_with_env("PATH=/nonexistent", kTinyRun + std::string("--out ") + out.string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_EQ(occurrences(o.output, "plots skipped"), 1) << o.output;
  EXPECT_THAT(o.output, HasSubstr("gnuplot is not on PATH"));
  EXPECT_TRUE(std::filesystem::exists(out / "timeseries.csv"));
  EXPECT_FALSE(std::filesystem::exists(out / "noa.png"));
  std::filesystem::remove_all(out);
}

// `rates` and `compare` without gnuplot: they succeed, say so, and leave the plots' scripts
// and CSVs to draw later (`rates` wrote no plot file at all, `compare` failed with exit 1).
TEST(Cli, RatesAndCompareWithoutGnuplotKeepTheirScripts) {
  const auto rates = temp_dir("no-gnuplot-rates");
  const Outcome r =
      swarmagg_with_env("PATH=/nonexistent",
                        "rates worlds/examples/demo.yaml --set run.duration=30 --replicates 2 "
                        "--threads 1 --quiet --out " +
                            rates.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("rate plots not drawn"));
  EXPECT_TRUE(std::filesystem::exists(rates / "rates-escape.gp"));
  EXPECT_TRUE(std::filesystem::exists(rates / "rates-escape.csv"));
  // `run --rates` says it once, for its own plots and the rates' together.
  const auto run = temp_dir("no-gnuplot-run-rates");
  const Outcome both = swarmagg_with_env("PATH=/nonexistent",
                                         kTinyRun + std::string("--rates --out ") + run.string());
  EXPECT_EQ(both.exit_code, 0) << both.output;
  EXPECT_EQ(occurrences(both.output, "plots skipped"), 1) << both.output;
  EXPECT_EQ(occurrences(both.output, "not drawn"), 0) << both.output;
  EXPECT_TRUE(std::filesystem::exists(run / "rates-escape.gp"));
  std::filesystem::remove_all(run);
  const auto compare = temp_dir("no-gnuplot-compare");
  const Outcome c =
      swarmagg_with_env("PATH=/nonexistent",
                        "compare worlds/examples/demo.yaml --set run.duration=20 --replicates 2 "
                        "--threads 1 --progress never --out " +
                            compare.string());
  EXPECT_EQ(c.exit_code, 0) << c.output;
  EXPECT_THAT(c.output, HasSubstr("plots skipped: gnuplot is not on PATH"));
  EXPECT_TRUE(std::filesystem::exists(compare / "noa.gp"));
  EXPECT_TRUE(std::filesystem::exists(compare / "summary.txt"));
  std::filesystem::remove_all(rates);
  std::filesystem::remove_all(compare);
}

TEST(Cli, NoPlotsSkipsThemSilently) {
  const auto out = temp_dir("undrawn");
  const Outcome o = swarmagg(kTinyRun + std::string("--no-plots --out ") + out.string());
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_THAT(o.output, ::testing::Not(HasSubstr("plots")));
  EXPECT_FALSE(std::filesystem::exists(out / "noa.png"));
  EXPECT_FALSE(std::filesystem::exists(out / "plots"));
  std::filesystem::remove_all(out);
}

TEST(Cli, PlotRedrawsAStoredRunWithTheSameCsvsAndScripts) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  const auto run = temp_dir("plot-run"), redrawn = temp_dir("plot-redrawn");
  const Outcome ran = swarmagg(kTinyRun + std::string("--out ") + run.string());
  ASSERT_EQ(ran.exit_code, 0) << ran.output;
  const Outcome plotted = swarmagg("plot " + run.string() + " --out " + redrawn.string());
  ASSERT_EQ(plotted.exit_code, 0) << plotted.output;
  for (const char* png : {"noa.png", "states.png", "sizes.png"}) {
    EXPECT_TRUE(std::filesystem::exists(run / png)) << png;
    EXPECT_TRUE(std::filesystem::exists(redrawn / png)) << png;
  }
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(run / "plots")) {
    const auto name = entry.path().filename();
    EXPECT_EQ(file_text(entry.path()), file_text(redrawn / "plots" / name)) << name;
    ++files;
  }
  EXPECT_GE(files, 6);  // a script and at least one CSV per plot
  EXPECT_EQ(swarmagg("plot " + temp_dir("plot-nothing").string()).exit_code, 2);
  // A model cut short at a line's end reads as whole: its curves would stop there.
  const std::string model = file_text(run / "model.csv");
  std::ofstream(run / "model.csv", std::ios::trunc)
      << model.substr(0, model.find('\n', model.find(",original,100,")) + 1);
  const Outcome model_cut = swarmagg("plot " + run.string() + " --out " + redrawn.string());
  EXPECT_EQ(model_cut.exit_code, 2) << model_cut.output;
  EXPECT_THAT(model_cut.output, HasSubstr("model.csv: the model's original curve ends at time "));
  std::ofstream(run / "model.csv", std::ios::trunc) << model;
  // A timeseries cut short at a line's end reads as whole: it would be drawn as the run.
  const std::string whole = file_text(run / "timeseries.csv");
  std::ofstream(run / "timeseries.csv", std::ios::trunc)
      << whole.substr(0, whole.find('\n', whole.size() / 2) + 1);
  const Outcome cut = swarmagg("plot " + run.string() + " --out " + redrawn.string());
  EXPECT_EQ(cut.exit_code, 2) << cut.output;
  EXPECT_THAT(cut.output, HasSubstr("timeseries.csv: does not hold exactly the run's rows"));
  // Rows of as many lines that no run of the world writes: a count it cannot have, a step off
  // its record grid. (kTinyRun: 20 agents, rows every 10 steps; line 3 is replicate 0, step 10.)
  const auto with_line_3_cell = [&](std::size_t column, const std::string& value) {
    std::string text = whole;
    const auto begin = text.find('\n', text.find('\n') + 1) + 1;
    const auto end = text.find('\n', begin);
    std::vector<std::string> cells;
    std::stringstream line(text.substr(begin, end - begin));
    for (std::string cell; std::getline(line, cell, ',');) cells.push_back(cell);
    cells.at(column) = value;
    std::string edited;
    for (const std::string& cell : cells) edited += (edited.empty() ? "" : ",") + cell;
    text.replace(begin, end - begin, edited);
    std::ofstream(run / "timeseries.csv", std::ios::trunc) << text;
    return swarmagg("plot " + run.string() + " --out " + redrawn.string());
  };
  for (const auto& [column, value, said] :
       {std::tuple{1, "11", "line 3: expected replicate 0 at step 10"},
        std::tuple{3, "nan", "line 3: noa: expected a whole number from 0 to 10"},
        std::tuple{3, "-999", "line 3: noa: expected a whole number from 0 to 10"},
        std::tuple{3, "11", "line 3: noa: expected a whole number from 0 to 10"},
        std::tuple{4, "2.5", "line 3: searching: expected a whole number from 0 to 20"},
        std::tuple{10, "", "line 3: growths: expected a whole number of events"}}) {
    const Outcome refused = with_line_3_cell(static_cast<std::size_t>(column), value);
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_THAT(refused.output, HasSubstr(said)) << column << " = " << value;
  }
  // A comparison's or an unmerged sweep's folder: what it is, and what to plot instead.
  for (const auto& [marker, said] : {std::pair{"compare.json", "a comparison's folder"},
                                     std::pair{"sweep.json", "a sweep's folder not merged yet"}}) {
    const auto other = temp_dir(std::string("plot-") + marker);
    std::filesystem::create_directories(other);
    std::ofstream(other / marker) << "{}\n";
    const Outcome refused = swarmagg("plot " + other.string());
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_THAT(refused.output, HasSubstr(said));
    std::filesystem::remove_all(other);
  }
  std::filesystem::remove_all(run);
  std::filesystem::remove_all(redrawn);
}

// A run folder's texts reach the plots' titles: gnuplot runs text between backquotes, and a
// line break would start a command of its own. Plotting a folder someone else made must not
// run anything.
TEST(Cli, PlotTitlesNeverRunTheTextTheyShow) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  const auto run = temp_dir("plot-quoted");
  ASSERT_EQ(swarmagg(kTinyRun + std::string("--no-plots --out ") + run.string()).exit_code, 0);
  const auto ran = run / "ran-a-command";
  nlohmann::json summary = nlohmann::json::parse(file_text(run / "summary.json"));
  summary["overrides"] = {"x=`touch " + ran.string() + "`", "y=1\n!touch " + ran.string() + "\n",
                          "z='quoted'"};
  std::ofstream(run / "summary.json", std::ios::trunc) << summary.dump();
  const Outcome plotted = swarmagg("plot " + run.string());
  EXPECT_EQ(plotted.exit_code, 0) << plotted.output;
  EXPECT_FALSE(std::filesystem::exists(ran));
  EXPECT_THAT(file_text(run / "plots" / "noa.gp"), HasSubstr("z=''quoted''"));
  std::filesystem::remove_all(run);
}

}  // namespace
