#include "config/world_loader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "config/world_writer.hpp"
#include "core/errors.hpp"

namespace swarmagg {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

std::string error_of(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
  try {
    load_world_text(yaml, "w.yaml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(WorldLoader, AMinimalWorldGetsEveryDefault) {
  const WorldSpec spec = load_world_text("robots: {count: 50}\n", "w.yaml");
  EXPECT_EQ(spec.robots.count, 50);
  EXPECT_DOUBLE_EQ(spec.robots.detection_radius, 4.0);
  EXPECT_DOUBLE_EQ(spec.engine.dt, 0.1);
  EXPECT_EQ(spec.arena.topology, Topology::Torus);
  EXPECT_EQ(spec.steps(), 50000);
}

TEST(WorldLoader, ReadsEveryBlock) {
  const WorldSpec spec = load_world_text(R"(
name: t
arena: {width: 90, height: 60, topology: walls}
robots: {count: 3, radius: 0.5, detection_radius: 3, speed: 2}
controller: {type: soysal, approach_radius: 9, p0: 0.001, leave_law: inverse_square}
engine: {type: box2d, dt: 0.05, box2d: {substeps: 2}}
run: {duration: 10, replicates: 2, seed: 99, record_every: 5}
model: {kappa: maxwell, leaving: original, periphery_cap: false}
render: {every: 3, width: 320, height: 240}
)",
                                         "w.yaml");
  EXPECT_EQ(spec.name, "t");
  EXPECT_EQ(spec.arena.topology, Topology::Walls);
  EXPECT_DOUBLE_EQ(spec.robots.speed, 2.0);
  EXPECT_EQ(spec.controller.type, "soysal");
  EXPECT_EQ(spec.controller.leave_law, LeaveLaw::InverseSquare);
  EXPECT_EQ(spec.engine.type, EngineType::Box2D);
  EXPECT_EQ(spec.engine.box2d.substeps, 2);
  EXPECT_EQ(spec.run.seed, 99u);
  EXPECT_EQ(spec.model.kappa, Kappa::Maxwell);
  EXPECT_FALSE(spec.model.periphery_cap);
  EXPECT_EQ(spec.render.width, 320);
  EXPECT_DOUBLE_EQ(spec.sensing_radius(), 9.0);
}

TEST(WorldLoader, ExplicitPlacementSetsTheCount) {
  const WorldSpec spec =
      load_world_text("robots: {placement: [[10, 10, 90], [20, 10, 0]]}\n", "w.yaml");
  EXPECT_EQ(spec.robots.count, 2);
  EXPECT_EQ(spec.robots.placement[0], (PlacedAgent{10, 10, 90}));
}

TEST(WorldLoader, OverridesUseTheSameKeyPaths) {
  const WorldSpec spec = load_world_text("robots: {count: 50}\n", "w.yaml",
                                         {"robots.count=80", "controller.join=false"});
  EXPECT_EQ(spec.robots.count, 80);
  EXPECT_FALSE(spec.controller.join);
}

// A --set value is one YAML document, as a world file is; a deep one is named short.
TEST(WorldLoader, AnOverrideValueIsOneShortlyNamedDocument) {
  const auto refusal = [](const std::string& assignment) {
    try {
      load_world_text("robots: {count: 50}\n", "w.yaml", {assignment});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(refusal("robots.count=5\n---\n7"),
              HasSubstr("a second YAML document starts here; a --set value is one YAML document"));
  const std::string deep = refusal("robots.count=" + std::string(3000, '['));
  EXPECT_THAT(deep, HasSubstr("nested more than"));
  EXPECT_LT(deep.size(), 300u) << deep;
}

TEST(WorldLoader, TheResolvedWorldLoadsBackUnchanged) {
  const WorldSpec spec = load_world_text(
      "name: r\nrobots: {placement: [[10.25, 10, 33.5]]}\nengine: {dt: 0.07}\n"
      "controller: {p_leave: 0.0001}\n",
      "w.yaml");
  const std::string text = world_to_yaml(spec);
  EXPECT_EQ(world_to_yaml(load_world_text(text, "resolved.yaml")), text);
  EXPECT_THAT(text, HasSubstr("dt: 0.07"));
  EXPECT_THAT(text, HasSubstr("p_leave: 0.0001"));
}

// A leave timeout of 0 made the default return window (3 leave timeouts) 0, which the key
// refuses: the run folder's world.resolved.yaml did not load again.
TEST(WorldLoader, AZeroLeaveTimeoutResolvesToAWorldThatLoadsAgain) {
  const WorldSpec spec = load_world_text("controller: {leave_timeout: 0}\n", "w.yaml");
  EXPECT_DOUBLE_EQ(spec.return_window(), 3.0 * spec.engine.dt);
  const std::string text = world_to_yaml(spec);
  EXPECT_EQ(world_to_yaml(load_world_text(text, "resolved.yaml")), text);
  EXPECT_DOUBLE_EQ(load_world_text("controller: {leave_timeout: 4}\n", "w.yaml").return_window(),
                   12.0);
}

TEST(WorldLoader, CompactionDefaultsToTouchingSpacingAndFollowsTheRadius) {
  const WorldSpec spec = load_world_text("robots: {count: 5}\n", "w.yaml");
  EXPECT_TRUE(spec.controller.compaction.enabled);
  EXPECT_DOUBLE_EQ(spec.compaction_spacing(), 2.0);
  EXPECT_DOUBLE_EQ(spec.controller.compaction.gain, 1.0);
  EXPECT_DOUBLE_EQ(spec.controller.compaction.tolerance, 0.05);
  EXPECT_DOUBLE_EQ(load_world_text("robots: {radius: 1.5, detection_radius: 6}\n", "w.yaml")
                       .compaction_spacing(),
                   3.0);
  const WorldSpec set = load_world_text(
      "controller:\n  compaction: {enabled: false, spacing: 2.5, gain: 3, tolerance: 0}\n",
      "w.yaml");
  EXPECT_FALSE(set.controller.compaction.enabled);
  EXPECT_DOUBLE_EQ(set.compaction_spacing(), 2.5);
  EXPECT_DOUBLE_EQ(set.controller.compaction.gain, 3.0);
  EXPECT_DOUBLE_EQ(set.controller.compaction.tolerance, 0.0);
  // Written back resolved, so the written world says what ran.
  EXPECT_THAT(world_to_yaml(spec), HasSubstr("spacing: 2"));
  EXPECT_DOUBLE_EQ(
      load_world_text("{}", "w.yaml", {"controller.compaction.spacing=2.25"}).compaction_spacing(),
      2.25);
}

// A check across keys that an override failed names the override: the file alone is valid.
TEST(WorldLoaderErrors, ACheckFailedByAnOverrideNamesIt) {
  EXPECT_EQ(error_of("arena: {width: 100, height: 100}\n"), "no error");
  EXPECT_EQ(error_of("arena: {width: 100, height: 100}\n", {"arena.width=1"}),
            "w.yaml: arena.width: the arena (1 x 100) must be at least 10 wide and high: twice "
            "the largest sensing radius the controller reads (4) plus a body's diameter (2) (the "
            "world as changed by --set arena.width=1)");
  EXPECT_THAT(error_of("arena: {width: 1, height: 100}\n"),
              ::testing::EndsWith("diameter (2)"));  // no override to name
}

// On a torus two agents moving apart by 2 v dt must not meet through each other's far image,
// which a step's events (found from the nearest image at its start) would miss: v dt at most
// L/4 - s/2. A 10 x 10 torus at v dt = 2 let two searchers pass each other unseen.
TEST(WorldLoaderErrors, ATorusStepMayNotReachTheFarImage) {
  const std::string small =
      "arena: {width: 10, height: 10, topology: TOPOLOGY}\nrobots: {count: 2, "
      "speed: SPEED}\n";
  const auto world = [&](const std::string& topology, const std::string& speed) {
    std::string text = small;
    text.replace(text.find("TOPOLOGY"), 8, topology);
    text.replace(text.find("SPEED"), 5, speed);
    return error_of(text);
  };
  EXPECT_THAT(world("torus", "20"),
              HasSubstr("robots.speed: moves an agent 2 per step (robots.speed * engine.dt), more "
                        "than 0.5: a quarter of the arena's shorter side less half the sensing "
                        "radius"));
  EXPECT_EQ(world("torus", "5"), "no error");   // 0.5 per step
  EXPECT_EQ(world("walls", "20"), "no error");  // no far image: a quarter of the side, 2.5
  EXPECT_THAT(world("walls", "30"), HasSubstr("more than 2.5: a quarter of the arena's shorter"));
}

// engine.contact: slide (the default) or stop, which the kinematic engine alone offers.
TEST(WorldLoaderErrors, ContactResponseIsCheckedAgainstTheEngine) {
  EXPECT_THAT(error_of("engine: {contact: bounce}\n"),
              HasSubstr("engine.contact: expected one of: slide, stop, got 'bounce'"));
  EXPECT_THAT(error_of("engine: {type: box2d, contact: stop}\n"),
              HasSubstr("engine.contact: is stop, which only the kinematic engine offers"));
  EXPECT_EQ(error_of("engine: {contact: stop}\n"), "no error");
  EXPECT_EQ(error_of("engine: {type: box2d, contact: slide}\n"), "no error");
}

TEST(WorldLoaderErrors, CompactionValuesAreChecked) {
  EXPECT_THAT(error_of("controller: {compaction: {spacing: 0}}\n"),
              HasSubstr("controller.compaction.spacing: expected a length from 1e-30 to 1e30"));
  EXPECT_THAT(error_of("controller: {compaction: {gain: -1}}\n"),
              HasSubstr("controller.compaction.gain: expected a positive number"));
  EXPECT_THAT(error_of("controller: {compaction: {tolerance: -0.1}}\n"),
              HasSubstr("controller.compaction.tolerance: expected a number from 0 to 1e30"));
  EXPECT_THAT(error_of("controller: {compaction: {spacing: 4}}\n"),
              HasSubstr("controller.compaction.spacing: is 4 but must be below "
                        "robots.detection_radius (4)"));
  EXPECT_THAT(error_of("robots: {radius: 2, detection_radius: 4}\n"),
              HasSubstr("is 4 (2 robots.radius) but must be below"));
  EXPECT_EQ(error_of("robots: {radius: 2, detection_radius: 4}\n"
                     "controller: {compaction: {enabled: false}}\n"),
            "no error");
  EXPECT_THAT(error_of("controller: {compaction: {spacng: 2}}\n"),
              HasSubstr("did you mean 'controller.compaction.spacing'"));
}

TEST(WorldLoaderErrors, AMissingFileIsNamed) {
  try {
    load_world("/nonexistent/w.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("/nonexistent/w.yaml: cannot open the world file (no such file)"));
  }
}

// A device has no end: reading /dev/zero as a world grew without bound. A folder is named as
// one. Both are refused before anything is read.
TEST(WorldLoaderErrors, ADeviceOrAFolderIsNoWorldFile) {
  const auto message = [](const std::string& path) {
    try {
      load_world(path);
      return std::string("accepted");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_THAT(message("/dev/zero"), HasSubstr("/dev/zero: is a device or a socket, not a file"));
  EXPECT_THAT(message("/tmp"), HasSubstr("/tmp: is a folder; expected a world file"));
}

TEST(WorldLoaderErrors, SyntaxErrorsGiveTheLine) {
  EXPECT_THAT(error_of("robots:\n  count: [1, 2\n"),
              AllOf(HasSubstr("w.yaml:"), HasSubstr("YAML syntax error")));
}

TEST(WorldLoaderErrors, UnknownKeysSuggestTheClosestKnownOne) {
  EXPECT_THAT(error_of("robots:\n  cont: 5\n"),
              AllOf(HasSubstr("w.yaml:2:3"), HasSubstr("unknown key 'robots.cont'"),
                    HasSubstr("did you mean 'robots.count'")));
  EXPECT_THAT(error_of("engine: {dtt: 0.1}\n"), HasSubstr("did you mean 'engine.dt'"));
  EXPECT_THAT(error_of("{}", {"robot.count=3"}), HasSubstr("did you mean 'robots.count'"));
}

// A controller key the file gives that its controller never reads would be dropped without a
// word (a Soysal key left in a file switched to Bayindir): refused, naming who reads it. So is
// the same key from --set or a sweep point, which summary.json would list as a change the run
// never made. `reproduce --set`, one override for worlds of every controller, applies its
// overrides itself and is not checked.
TEST(WorldLoaderErrors, ControllerKeysTheControllerDoesNotReadAreRefused) {
  EXPECT_THAT(error_of("controller:\n  type: bayindir\n  approach_radius: 12\n"),
              AllOf(HasSubstr("w.yaml:3:3"), HasSubstr("controller.approach_radius"),
                    HasSubstr("controller type 'bayindir' does not read this key"),
                    HasSubstr("read by controller type 'soysal'")));
  EXPECT_THAT(error_of("controller: {type: soysal, approach_radius: 12, p_leave: 0.1}\n"),
              HasSubstr("controller.p_leave: controller type 'soysal' does not read this key"));
  EXPECT_EQ(error_of("controller: {type: soysal, approach_radius: 12}\n"), "no error");
  EXPECT_EQ(error_of("controller: {type: soysal, tumble: 0.001}\n"), "no error");
  EXPECT_THAT(error_of("controller: {type: bayindir}\n", {"controller.approach_radius=12"}),
              AllOf(HasSubstr("--set: controller.approach_radius: the world's controller type "
                              "'bayindir' (w.yaml) does not read this key"),
                    HasSubstr("read by controller type 'soysal'"),
                    HasSubstr("remove it or set controller.type too")));
  EXPECT_EQ(error_of("controller: {type: bayindir}\n", {"controller.p_leave=0.5"}), "no error");
  // A file whose controller.type an override sets (a sweep over controller types) may hold
  // keys for each of them.
  EXPECT_EQ(
      error_of("controller: {type: bayindir, approach_radius: 12}\n", {"controller.type=soysal"}),
      "no error");
  // Not so the overrides: they act on the type they set (a sweep over controller types marks
  // the keys that one of its types reads, tests/sweep/sweep_runs_test.cpp).
  EXPECT_THAT(error_of("controller: {type: bayindir}\n",
                       {"controller.type=soysal", "controller.p_leave=0.5"}),
              HasSubstr("controller.p_leave: the world's controller type 'soysal'"));
}

// Each family of models reads some model.* keys (kappa and the creation variant the Bayindir
// equations and the encounter rate, the leaving variant the Soysal chain): --set or a sweep
// point giving one the world's model ignores would be listed as a change that changed nothing.
// A file may hold them, and the resolved world writes them all.
TEST(WorldLoaderErrors, ModelKeysTheModelDoesNotReadAreRefusedFromOverrides) {
  const std::string soysal = "controller: {type: soysal}\n";
  EXPECT_THAT(error_of(soysal, {"model.kappa=maxwell"}),
              AllOf(HasSubstr("--set: model.kappa: the model of the world's controller type "
                              "'soysal' (w.yaml) does not read this key"),
                    HasSubstr("read by the models of controller type 'bayindir', 'collision'"),
                    HasSubstr("remove it or set controller.type too")));
  EXPECT_THAT(error_of(soysal, {"model.stochastic_replicates=0"}),
              HasSubstr("model.stochastic_replicates: the model of"));
  EXPECT_EQ(error_of(soysal, {"model.leaving=original"}), "no error");
  EXPECT_THAT(error_of("controller: {type: bayindir}\n", {"model.periphery_cap=false"}),
              AllOf(HasSubstr("model.periphery_cap: the model of the world's controller type "
                              "'bayindir'"),
                    HasSubstr("read by the models of controller type 'soysal'")));
  EXPECT_EQ(error_of("controller: {type: collision}\n", {"model.kappa=maxwell"}), "no error");
  EXPECT_THAT(error_of("controller: {type: cockroach}\n", {"model.initial_state=all_searching"}),
              HasSubstr("the world's controller type 'cockroach' (w.yaml) has no model, so the "
                        "run would ignore it"));
  // Overrides that set the type act on the type they set.
  EXPECT_EQ(error_of(soysal, {"controller.type=bayindir", "model.kappa=maxwell"}), "no error");

  // `measured` needs a run's rates even where the encounter rate starts from nothing.
  EXPECT_EQ(error_of("controller: {type: collision}\n", {"model.initial_state=all_searching"}),
            "no error");

  // The resolved world keeps every model key: switched to Bayindir, a resolved Soysal world
  // gives its model what the file said, as the file itself does.
  const std::string soysal_file = "controller: {type: soysal}\nmodel: {kappa: paper}\n";
  const std::string resolved = world_to_yaml(load_world_text(soysal_file, "w.yaml"));
  EXPECT_THAT(resolved, HasSubstr("kappa: paper"));
  for (const std::string& text : {soysal_file, resolved}) {
    EXPECT_EQ(load_world_text(text, "w.yaml", {"controller.type=bayindir"}).model.kappa,
              Kappa::Paper);
  }
}

// A key given no value is named where it stands, not where the next token starts.
TEST(WorldLoaderErrors, AMissingValueNamesTheLineOfItsKey) {
  EXPECT_THAT(error_of("robots:\n  count:\n"),
              AllOf(HasSubstr("w.yaml:2:3: robots.count"), HasSubstr("got nothing")));
}

TEST(WorldLoaderErrors, WrongTypesSayWhatWasExpected) {
  EXPECT_THAT(error_of("robots:\n  count: many\n"),
              AllOf(HasSubstr("w.yaml:2:10"), HasSubstr("robots.count: expected a whole number"),
                    HasSubstr("got 'many'")));
  EXPECT_THAT(error_of("controller: {join: maybe}\n"),
              HasSubstr("controller.join: expected true or false"));
  EXPECT_THAT(error_of("arena: {topology: sphere}\n"), HasSubstr("one of: torus, walls"));
  EXPECT_THAT(error_of("robots: 5\n"), HasSubstr("robots: expected a mapping of keys"));
  EXPECT_THAT(error_of("robots: {radius: [1]}\n"), HasSubstr("got a list"));
}

TEST(WorldLoaderErrors, ImpossibleValuesAreRefused) {
  EXPECT_THAT(error_of("robots: {radius: -1}\n"),
              HasSubstr("robots.radius: expected a length from 1e-30 to 1e30"));
  EXPECT_THAT(error_of("engine: {dt: 0}\n"), HasSubstr("engine.dt: expected a positive number"));
  EXPECT_THAT(error_of("robots: {radius: 3, detection_radius: 4}\n"),
              HasSubstr("robots.detection_radius: must be at least twice robots.radius"));
  EXPECT_THAT(error_of("arena: {width: 20, height: 20}\nrobots: {count: 1000}\n"),
              HasSubstr("robots.count: 1000 agents"));
  EXPECT_THAT(error_of("controller: {p_leave: 1.5}\n"), HasSubstr("a probability between 0 and 1"));
  // Box2D's float would make it infinite and abort on its own check.
  EXPECT_THAT(error_of("engine: {box2d: {linear_damping: 1e39}}\n"),
              HasSubstr("engine.box2d.linear_damping: expected a number from 0 to 1e30"));
  EXPECT_THAT(error_of("arena: {width: .nan}\n"),
              HasSubstr("arena.width: expected a length from 1e-30 to 1e30"));
  EXPECT_THAT(error_of("arena: {width: 1e999}\n"),
              HasSubstr("arena.width: expected a length from 1e-30 to 1e30"));
  EXPECT_THAT(error_of("robots: {count: 99999999999999999999}\n"), HasSubstr("robots.count"));
}

TEST(WorldLoaderErrors, EmptyOrNonMappingDocumentsAreRefused) {
  EXPECT_THAT(error_of(""), HasSubstr("the world file is empty"));
  EXPECT_THAT(error_of("- 1\n- 2\n"), HasSubstr("expected a mapping of world keys"));
}

TEST(WorldLoaderErrors, PlacementMustFitTheCountAndTheArena) {
  EXPECT_THAT(error_of("robots: {count: 3, placement: [[1, 1, 0]]}\n"),
              HasSubstr("lists 1 agents but robots.count is 3"));
  EXPECT_THAT(error_of("robots: {placement: [[500, 1, 0]]}\n"), HasSubstr("is outside"));
  EXPECT_THAT(error_of("robots: {placement: [[1, 1]]}\n"), HasSubstr("[x, y, heading_deg]"));
}

TEST(WorldLoaderErrors, DuplicateKeysAreRefused) {
  EXPECT_THAT(error_of("robots: {count: 3, count: 4}\n"), HasSubstr("given twice"));
}

}  // namespace
}  // namespace swarmagg
