#include "sweep/sweep_runs.hpp"

#include <gmock/gmock.h>

#include "core/errors.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;
using testing::SweepTest;

TEST(SweepPoints, AreTheGridWithTheFirstParameterSlowest) {
  const auto points =
      sweep_points({{"robots.count", {"10", "20"}}, {"robots.speed", {"1", "2", "3"}}});
  ASSERT_EQ(points.size(), 6u);
  EXPECT_EQ(points[0].id, "robots.count=10,robots.speed=1");
  EXPECT_EQ(points[2].id, "robots.count=10,robots.speed=3");
  EXPECT_EQ(points[3].id, "robots.count=20,robots.speed=1");
  EXPECT_EQ(points[5].index, 5);
  EXPECT_EQ(describe_point(points[4]), "robots.count=20 robots.speed=2");
}

TEST(SweepPoints, LongIdsStayShortAndUnique) {
  std::vector<SweepParameter> parameters;
  for (const char* key : {"controller.leave_timeout", "controller.approach_radius", "controller.p0",
                          "controller.p_leave", "controller.tumble", "robots.detection_radius",
                          "robots.radius", "robots.speed", "arena.width", "arena.height"}) {
    parameters.push_back({key, {"0.000123456789"}});
  }
  parameters.back().values.push_back("0.000123456788");
  const auto points = sweep_points(parameters);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_LE(points[0].id.size(), 200u);
  EXPECT_NE(points[0].id, points[1].id);
}

// A point whose controller would ignore a swept key would differ from its neighbours only in
// its seed, while its folder and the merged tables name the key as changed.
TEST_F(SweepTest, APointSettingAKeyItsControllerDoesNotReadIsRefused) {
  const SweepPlan plan = load_sweep(
      sweep_file("base: worlds/tiny.yaml\nparameters:\n  controller.approach_radius: [8, 12]\n"));
  try {
    expand_sweep(plan);
    ADD_FAILURE() << "a Bayindir sweep over approach_radius was accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("parameters: controller.approach_radius: the world's "
                                    "controller type 'bayindir' ("));
    EXPECT_THAT(e.what(), HasSubstr("(point controller.approach_radius=8)) does not read"));
  }
  // A sweep over controller types sets each type's keys in every point.
  const SweepPlan types = load_sweep(
      sweep_file("base: worlds/tiny.yaml\nparameters:\n  controller.type: [bayindir, soysal]\n"
                 "  controller.p_leave: [0.001]\n",
                 "types.yaml"));
  EXPECT_EQ(expand_sweep(types).size(), 2u * 5u);
  // A key none of the swept types reads is refused.
  const SweepPlan none = load_sweep(
      sweep_file("base: worlds/tiny.yaml\nparameters:\n  controller.type: [bayindir, cockroach]\n"
                 "  controller.approach_radius: [8]\n",
                 "none.yaml"));
  EXPECT_THROW(expand_sweep(none), InputError);
  // Model keys too: a Soysal sweep over kappa would plot a parameter that changed nothing.
  const SweepPlan kappa =
      load_sweep(sweep_file("base: worlds/tiny.yaml\nparameters:\n  controller.type: [soysal]\n"
                            "  model.kappa: [kinetic, maxwell]\n",
                            "kappa.yaml"));
  EXPECT_THROW(expand_sweep(kappa), InputError);
  const SweepPlan models = load_sweep(
      sweep_file("base: worlds/tiny.yaml\nparameters:\n  controller.type: [bayindir, soysal]\n"
                 "  model.kappa: [maxwell]\n",
                 "models.yaml"));
  EXPECT_EQ(expand_sweep(models).size(), 2u * 5u);
}

// A base world's model keys reach every point of a sweep over controller types, whichever
// type the base file names: a Soysal base holding kappa: paper gives it to its Bayindir points
// (the sweep keeps the base as a resolved world, which writes every model key).
TEST_F(SweepTest, ASweepOverControllerTypesKeepsTheBaseWorldsModelKeys) {
  testing::write_file_text(dir_ / "worlds" / "soysal.yaml",
                           "arena: {width: 60, height: 60}\nrobots: {count: 5}\n"
                           "controller: {type: soysal}\nrun: {duration: 100, replicates: 2}\n"
                           "model: {kappa: paper, stochastic_replicates: 0}\n");
  const SweepPlan plan = load_sweep(
      sweep_file("base: worlds/soysal.yaml\nparameters:\n  controller.type: [soysal, bayindir]\n"));
  for (const SweepRun& run : expand_sweep(plan)) {
    EXPECT_EQ(run.world.model.kappa, Kappa::Paper) << run.world.controller.type;
    EXPECT_EQ(run.world.model.stochastic_replicates, 0) << run.world.controller.type;
  }
}

// A sweep read back from its folder (merge) is not refused for keys its points'
// models ignore: its points were checked when it began, and a version that did not check
// model keys may have begun it (a Soysal sweep over model.kappa).
TEST_F(SweepTest, ARecordedSweepIsNotRefusedForKeysItsModelsIgnore) {
  SweepPlan plan =
      load_sweep(sweep_file("base: worlds/tiny.yaml\nparameters:\n  controller.type: [soysal]\n"
                            "  robots.count: [5]\n"));
  plan.parameters.push_back({"model.kappa", {"kinetic", "maxwell"}});
  EXPECT_THROW(expand_sweep(plan), InputError);
  plan.recorded = true;
  EXPECT_EQ(expand_sweep(plan).size(), 2u * 5u);
}

TEST_F(SweepTest, EachRunIsOneReplicateWithItsOwnSeed) {
  const std::vector<SweepRun> runs = expand_sweep(load_sweep(sweep_file(testing::kGridSweep)));
  ASSERT_EQ(runs.size(), 12u);
  const SweepRun& run = runs[5];  // point 2 (count 10, p 0.005), replicate 1
  EXPECT_EQ(run.index, 5);
  EXPECT_EQ(run.replicate, 1);
  EXPECT_EQ(run.point.id, "robots.count=10,controller.p_leave=0.005");
  EXPECT_EQ(run.world.robots.count, 10);
  EXPECT_DOUBLE_EQ(run.world.controller.p_leave, 0.005);
  EXPECT_EQ(run.world.run.replicates, 1);
  EXPECT_EQ(run.world.run.seed, run.seed);
  EXPECT_EQ(run.world.arena.width, 60.0);  // from the base world
  EXPECT_EQ(sweep_run_folder("out", run),
            std::filesystem::path("out/runs/robots.count=10,controller.p_leave=0.005/rep-1"));
}

TEST_F(SweepTest, APointTheWorldRejectsIsNamed) {
  const SweepPlan plan = load_sweep(sweep_file(
      "base: worlds/tiny.yaml\nparameters: {robots.count: [10, 1200]}\nreplicates: 1\n"));
  try {
    expand_sweep(plan);
    FAIL() << "1200 agents fit in a 60 x 60 arena";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("grid.yaml (point robots.count=1200)"));
    EXPECT_THAT(e.what(), HasSubstr("robots.count"));
  }
}

}  // namespace
}  // namespace swarmagg
