// A controller of this test suite declares its own keys with the key table's builders (a
// whole number, a probability, a name, a flag) and they act like core keys: in world
// files, --set, the resolved world and a sweep over a scalar key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "config/world_keys.hpp"
#include "config/world_loader.hpp"
#include "config/world_override.hpp"
#include "config/world_writer.hpp"
#include "controllers/cockroach/cockroach_controller.hpp"
#include "controllers/controller_registry.hpp"
#include "core/errors.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_merge.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// A quorum rule: a searcher stops only beside at least `quorum` waiting agents (Jeanson et
// al. 2005's threshold form), built on the neighbour-count controller.
const WorldKey& quorum_key() {
  static const WorldKey key = whole_number_key("controller.quorum", 2, 1, 8, "quorum");
  return key;
}
const WorldKey& stop_key() {
  static const WorldKey key = probability_key("controller.stop", 0.5, "quorum");
  return key;
}
const WorldKey& rule_key() {
  static const WorldKey key =
      name_choice_key("controller.rule", "threshold", {"threshold", "any"}, "quorum");
  return key;
}
const WorldKey& leaving_key() {
  static const WorldKey key = flag_key("controller.leaving", true, "quorum");
  return key;
}

CockroachParameters quorum_parameters(const WorldSpec& spec) {
  const double stop = number(spec, stop_key());
  const long long quorum =
      name_choice(spec, rule_key()) == "any" ? 1 : whole_number(spec, quorum_key());
  CockroachParameters p;
  p.stop_probability.assign(static_cast<std::size_t>(quorum - 1), 0.0);
  p.stop_probability.push_back(stop);
  p.leave_probability = {flag(spec, leaving_key()) ? 0.01 : 0.0};
  p.leave_timeout = spec.controller.leave_timeout;
  p.speed = spec.robots.speed;
  p.dt = spec.engine.dt;
  p.detection_radius = spec.robots.detection_radius;
  p.compaction.enabled = false;
  return p;
}

double detection_radius(const WorldSpec& spec) {
  return spec.robots.detection_radius;
}

ControllerRegistration quorum_registration() {
  ControllerRegistration r;
  r.world = {"quorum",         {quorum_key(), stop_key(), rule_key(), leaving_key()},
             detection_radius, detection_radius,
             nullptr,          {"controller.leave_timeout"}};
  r.make = [](const WorldSpec& spec) -> std::unique_ptr<Controller> {
    return std::make_unique<CockroachController>(quorum_parameters(spec));
  };
  r.rules = [](const WorldSpec& spec) {
    ControllerRules rules;
    rules.allowed_states =
        state_bit(AgentState::Go) | state_bit(AgentState::Wait) | state_bit(AgentState::Leave);
    rules.joins = true;
    rules.leaves = true;
    rules.leaving_happens = flag(spec, leaving_key());
    rules.model = ModelFamily::None;
    return rules;
  };
  return r;
}

// Before main, so before any world is read.
const bool kRegistered = (register_controller(quorum_registration()), true);

const char* kQuorumWorld = R"(name: quorum-world
arena: {width: 60, height: 60}
robots: {count: 20}
controller:
  type: quorum
  quorum: 3
  rule: threshold
run: {duration: 100, replicates: 2, seed: 3, record_every: 50}
)";

class ControllerKeys : public testing::SweepTest {
 protected:
  void SetUp() override {
    SweepTest::SetUp();
    testing::write_file_text(dir_ / "worlds" / "quorum.yaml", kQuorumWorld);
  }
  WorldSpec load(const std::vector<std::string>& overrides = {}) const {
    return load_world((dir_ / "worlds" / "quorum.yaml").string(), overrides);
  }
  std::string load_error(const std::vector<std::string>& overrides) const {
    try {
      load(overrides);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }
};

TEST_F(ControllerKeys, AWorldFileAndSetReadThemAsScalars) {
  ASSERT_TRUE(kRegistered);
  const WorldSpec world = load();
  EXPECT_EQ(whole_number(world, quorum_key()), 3);
  EXPECT_EQ(number(world, stop_key()), 0.5);  // the fallback
  EXPECT_EQ(quorum_parameters(world).stop_probability, (std::vector<double>{0.0, 0.0, 0.5}));
  const WorldSpec set = load({"controller.quorum=2", "controller.rule=any",
                              "controller.leaving=false", "controller.stop=0.25"});
  EXPECT_EQ(whole_number(set, quorum_key()), 2);
  EXPECT_EQ(name_choice(set, rule_key()), "any");
  EXPECT_FALSE(flag(set, leaving_key()));
  EXPECT_EQ(number(set, stop_key()), 0.25);
}

TEST_F(ControllerKeys, BadValuesGetTheMessagesOfCoreKeys) {
  EXPECT_THAT(load_error({"controller.quorum=[2]"}),
              HasSubstr("controller.quorum: expected a whole number from 1 to 8"));
  EXPECT_THAT(load_error({"controller.quorum=0"}), HasSubstr("a whole number from 1 to 8"));
  EXPECT_THAT(load_error({"controller.stop=1.5"}),
              HasSubstr("controller.stop: expected a probability between 0 and 1"));
  EXPECT_THAT(load_error({"controller.rule=sometimes"}),
              HasSubstr("controller.rule: expected one of: threshold, any"));
  EXPECT_THAT(load_error({"controller.leaving=maybe"}),
              HasSubstr("controller.leaving: expected true or false"));
  EXPECT_THAT(load_error({"controller.quorom=2"}), HasSubstr("controller.quorum"));  // did you mean
  // In the file too, with its line.
  testing::write_file_text(dir_ / "worlds" / "bad.yaml",
                           "controller:\n  type: quorum\n  quorum: 2.5\n");
  try {
    load_world((dir_ / "worlds" / "bad.yaml").string());
    ADD_FAILURE() << "2.5 accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("bad.yaml:3:"));
    EXPECT_THAT(e.what(), HasSubstr("a whole number from 1 to 8"));
  }
}

TEST_F(ControllerKeys, TheResolvedWorldListsOnlyTheKeysItsControllerReads) {
  const std::string text = world_to_yaml(load());
  EXPECT_THAT(text, HasSubstr("quorum: 3"));
  EXPECT_THAT(text, HasSubstr("stop: 0.5"));
  EXPECT_THAT(text, HasSubstr("rule: threshold"));
  EXPECT_THAT(text, HasSubstr("leaving: true"));
  EXPECT_THAT(text, HasSubstr("leave_timeout: 10"));
  for (const char* other : {"p_leave", "join:", "leave:", "approach_radius", "p0", "leave_law",
                            "collision_mode", "tumble", "stop_probability", "compaction"}) {
    EXPECT_THAT(text, Not(HasSubstr(other))) << other;
  }
  // It reads back as the same world.
  EXPECT_EQ(world_to_yaml(load_world_text(text, "resolved")), text);
}

TEST_F(ControllerKeys, ABayindirWorldShowsNoKeyOfSoysalsOrTheCollisionCheck) {
  const std::string text =
      world_to_yaml(load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml"));
  EXPECT_THAT(text, HasSubstr("p_leave:"));
  for (const char* other : {"approach_radius", "p0", "leave_law", "leave_size", "collision_mode",
                            "tumble", "stop_probability", "quorum"}) {
    EXPECT_THAT(text, Not(HasSubstr(other))) << other;
  }
}

TEST_F(ControllerKeys, ASweepRunsAScalarKeyOverThreeValues) {
  const std::string sweep = sweep_file(R"(name: quorums
base: worlds/quorum.yaml
parameters:
  controller.quorum: [1, 2, 3]
replicates: 2
seed: 5
)");
  const SweepPlan plan = load_sweep(sweep);
  ASSERT_EQ(plan.parameters.size(), 1u);
  EXPECT_EQ(plan.parameters[0].values, (std::vector<std::string>{"1", "2", "3"}));
  SweepOptions options;
  options.out = dir_ / "out";
  options.threads = 2;
  const SweepReport report = run_sweep(plan, options);
  EXPECT_EQ(report.ran, 6);
  const std::vector<SweepRun> runs = expand_sweep(plan);
  for (const SweepRun& run : runs) {
    const WorldSpec ran =
        load_world((sweep_run_folder(options.out, run) / "world.resolved.yaml").string());
    EXPECT_EQ(whole_number(ran, quorum_key()), run.point.index + 1);
  }
  const MergeReport merged = merge_sweep({options.out}, options.out);
  EXPECT_EQ(merged.points, 3);
  EXPECT_THAT(testing::read_file_text(options.out / "sweep_summary.csv"),
              HasSubstr("controller.quorum"));
}

}  // namespace
}  // namespace swarmagg
