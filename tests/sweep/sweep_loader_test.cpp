#include "sweep/sweep_loader.hpp"

#include <gmock/gmock.h>

#include "core/errors.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using testing::SweepTest;

class SweepLoaderTest : public SweepTest {
 protected:
  // The message load_sweep refuses `body` with.
  std::string refusal(const std::string& body) {
    const std::string path = sweep_file(body);
    try {
      load_sweep(path);
    } catch (const InputError& e) {
      return e.what();
    }
    ADD_FAILURE() << "accepted:\n" << body;
    return "";
  }
};

TEST_F(SweepLoaderTest, ReadsTheGridInFileOrderWithCanonicalValues) {
  const SweepPlan plan = load_sweep(sweep_file(R"(name: grid-test
base: worlds/tiny.yaml
parameters:
  robots.count: [10, 20]
  controller.p_leave: [1e-3, 0.0050]
  arena.topology: [torus, walls]
replicates: 4
seed: 99
)"));
  EXPECT_EQ(plan.name, "grid-test");
  EXPECT_EQ(plan.replicates, 4);
  EXPECT_EQ(plan.seed, 99u);
  ASSERT_EQ(plan.parameters.size(), 3u);
  EXPECT_EQ(plan.parameters[0], (SweepParameter{"robots.count", {"10", "20"}}));
  EXPECT_EQ(plan.parameters[1], (SweepParameter{"controller.p_leave", {"0.001", "0.005"}}));
  EXPECT_EQ(plan.parameters[2], (SweepParameter{"arena.topology", {"torus", "walls"}}));
  // Each run is one replicate and draws no frames; the rest is the base world.
  EXPECT_THAT(plan.base_world,
              AllOf(HasSubstr("replicates: 1"), HasSubstr("every: 0"), HasSubstr("width: 60")));
}

TEST_F(SweepLoaderTest, DefaultsComeFromTheFileNameAndTheBaseWorld) {
  const SweepPlan plan = load_sweep(
      sweep_file("base: worlds/tiny.yaml\nparameters: {robots.count: [10]}\n", "count-sweep.yaml"));
  EXPECT_EQ(plan.name, "count-sweep");
  EXPECT_EQ(plan.replicates, 5);  // tiny.yaml's run.replicates
  EXPECT_EQ(plan.seed, 3u);       // tiny.yaml's run.seed
}

TEST_F(SweepLoaderTest, RefusesAnUnknownKeyPathNamingLineAndSuggestion) {
  const std::string message = refusal(
      "base: worlds/tiny.yaml\nparameters:\n  robots.count: [10]\n  controller.pleave: [0.1]\n");
  EXPECT_THAT(message,
              AllOf(HasSubstr("grid.yaml:4:3"), HasSubstr("unknown world key 'controller.pleave'"),
                    HasSubstr("did you mean 'controller.p_leave'?")));
}

TEST_F(SweepLoaderTest, RefusesAnEmptyList) {
  const std::string message =
      refusal("base: worlds/tiny.yaml\nparameters:\n  robots.count: []\nreplicates: 2\n");
  EXPECT_THAT(message, AllOf(HasSubstr("grid.yaml:3:17"), HasSubstr("robots.count"),
                             HasSubstr("expected a non-empty list of values"),
                             HasSubstr("got an empty list")));
}

TEST_F(SweepLoaderTest, RefusesAScalarWhereAListBelongs) {
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {robots.count: 10}\n"),
              AllOf(HasSubstr("robots.count"), HasSubstr("non-empty list"), HasSubstr("got '10'")));
}

TEST_F(SweepLoaderTest, ChecksEveryValueAgainstItsWorldKey) {
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters:\n  controller.p_leave: [0.1, 2]\n"),
              AllOf(HasSubstr("grid.yaml:3:29"), HasSubstr("controller.p_leave"),
                    HasSubstr("a probability between 0 and 1"), HasSubstr("got '2'")));
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters:\n  arena.topology: [torus, donut]\n"),
              AllOf(HasSubstr("one of: torus, walls"), HasSubstr("got 'donut'")));
}

TEST_F(SweepLoaderTest, RefusesAValueListedTwiceUnderAnotherSpelling) {
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters:\n  controller.p_leave: [0.001, 1e-3]\n"),
              AllOf(HasSubstr("'1e-3'"), HasSubstr("listed twice")));
}

TEST_F(SweepLoaderTest, RefusesUnknownSweepKeysWithASuggestion) {
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {robots.count: [10]}\nreplicate: 3\n"),
              AllOf(HasSubstr("grid.yaml:3:1"), HasSubstr("unknown sweep key 'replicate'"),
                    HasSubstr("did you mean 'replicates'?")));
}

TEST_F(SweepLoaderTest, RefusesKeysTheSweepSetsItself) {
  for (const std::string key : {"run.seed", "run.replicates", "name", "render.every"}) {
    EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {" + key + ": [1]}\n"),
                AllOf(HasSubstr(key), HasSubstr("cannot be swept")));
  }
}

TEST_F(SweepLoaderTest, RefusesMissingOrBrokenParts) {
  EXPECT_THAT(refusal("parameters: {robots.count: [10]}\n"), HasSubstr("missing 'base:'"));
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\n"), HasSubstr("missing 'parameters:'"));
  EXPECT_THAT(refusal("base: worlds/none.yaml\nparameters: {robots.count: [10]}\n"),
              AllOf(HasSubstr("grid.yaml:1:7: base:"), HasSubstr("none.yaml")));
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {robots.count: [10]}\nseed: -1\n"),
              AllOf(HasSubstr("grid.yaml:3:7"), HasSubstr("seed")));
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {}\n"),
              HasSubstr("parameters: expected a mapping of world key paths to lists of values, "
                        "e.g. {robots.count: [50, 100]}, got an empty mapping"));
  EXPECT_THAT(refusal("base: [\n"), HasSubstr("YAML syntax error"));
  EXPECT_THAT(
      refusal("base: worlds/tiny.yaml\nparameters:\n  robots.count: [1]\n  robots.count: [2]\n"),
      HasSubstr("grid.yaml:4:3: parameters: 'robots.count' given twice"));
  EXPECT_THAT(
      refusal("base: worlds/tiny.yaml\nbase: worlds/tiny.yaml\nparameters: {robots.count: [1]}\n"),
      HasSubstr("grid.yaml:2:1: 'base' given twice"));
  EXPECT_THAT(refusal("- base\n"), HasSubstr("expected a sweep"));
  // yaml-cpp's Load kept the first document and dropped the second without a word.
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {robots.count: [10]}\n---\n"
                      "parameters: {robots.count: [30]}\n"),
              HasSubstr("grid.yaml:3:1: a second YAML document starts here; a sweep file is one "
                        "YAML document"));
  EXPECT_THAT(refusal("base: worlds/tiny.yaml\nparameters: {robots.count: " +
                      std::string(600, '[') + std::string(600, ']') + "}\n"),
              HasSubstr("nested more than"));
}

TEST_F(SweepLoaderTest, NamesAMissingSweepFile) {
  EXPECT_THROW(load_sweep((dir_ / "absent.yaml").string()), InputError);
}

}  // namespace
}  // namespace swarmagg
