#include "sweep/sweep_seed.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_runs.hpp"
#include "sweep_testing.hpp"

namespace swarmagg {
namespace {

using testing::SweepTest;

// Seed of each run by (point text, replicate), the identity that must not move.
std::map<std::pair<std::string, int>, std::uint64_t> seeds_by_identity(const SweepPlan& plan) {
  std::map<std::pair<std::string, int>, std::uint64_t> seeds;
  for (const SweepRun& run : expand_sweep(plan)) {
    seeds[{canonical_point_text(run.point.assignments), run.replicate}] = run.seed;
  }
  return seeds;
}

TEST_F(SweepTest, AddingAValueKeepsTheSeedsOfExistingRuns) {
  const auto before = seeds_by_identity(load_sweep(sweep_file(R"(base: worlds/tiny.yaml
parameters:
  robots.count: [10, 20]
  controller.p_leave: [0.001, 0.005]
replicates: 2
seed: 11
)")));
  const auto after = seeds_by_identity(load_sweep(sweep_file(R"(base: worlds/tiny.yaml
parameters:
  robots.count: [15, 10, 20]
  controller.p_leave: [0.001, 0.0001, 0.005]
replicates: 3
seed: 11
)")));
  ASSERT_EQ(before.size(), 8u);
  ASSERT_EQ(after.size(), 27u);
  for (const auto& [identity, seed] : before) EXPECT_EQ(after.at(identity), seed) << identity.first;
}

TEST_F(SweepTest, SeedsIgnoreParameterOrderButNotTheSweepSeed) {
  const auto ab =
      seeds_by_identity(load_sweep(sweep_file("base: worlds/tiny.yaml\nparameters: {robots.count: "
                                              "[10, 20], robots.speed: [1, 2]}\nseed: 5\n")));
  const auto ba =
      seeds_by_identity(load_sweep(sweep_file("base: worlds/tiny.yaml\nparameters: {robots.speed: "
                                              "[1, 2], robots.count: [10, 20]}\nseed: 5\n")));
  const auto other =
      seeds_by_identity(load_sweep(sweep_file("base: worlds/tiny.yaml\nparameters: {robots.count: "
                                              "[10, 20], robots.speed: [1, 2]}\nseed: 6\n")));
  EXPECT_EQ(ab, ba);
  for (const auto& [identity, seed] : ab) EXPECT_NE(other.at(identity), seed);
}

TEST(SweepSeed, DistinctRunsGetDistinctSeeds) {
  std::set<std::uint64_t> seeds;
  for (int count = 1; count <= 50; ++count) {
    for (int replicate = 0; replicate < 20; ++replicate) {
      seeds.insert(sweep_run_seed(1, {{"robots.count", std::to_string(count)}}, replicate));
    }
  }
  EXPECT_EQ(seeds.size(), 1000u);
}

TEST(SweepSeed, IsAFixedFunctionOfItsInputs) {
  // Pinned so that a change of the derivation, which would silently change every sweep's
  // results, fails here first.
  EXPECT_EQ(text_hash(""), 0xCBF29CE484222325ull);
  EXPECT_EQ(text_hash("a"), 0xAF63DC4C8601EC8Cull);
  EXPECT_EQ(canonical_point_text({{"robots.speed", "2"}, {"robots.count", "10"}}),
            "robots.count=10\nrobots.speed=2\n");
  EXPECT_EQ(sweep_run_seed(7, {{"robots.count", "10"}, {"controller.p_leave", "0.0005"}}, 0),
            14330859698695740548ull);
}

TEST(SweepSeed, DependsOnValuesNotOnHowNumbersArePrinted) {
  EXPECT_EQ(canonical_point_text({{"controller.p_leave", "0.0005"}}),
            canonical_point_text({{"controller.p_leave", "5e-04"}}));
  EXPECT_EQ(canonical_point_text({{"arena.width", "1000"}}),
            canonical_point_text({{"arena.width", "1e3"}}));
  EXPECT_NE(canonical_point_text({{"robots.count", "9007199254740993"}}),
            canonical_point_text({{"robots.count", "9007199254740992"}}));
  EXPECT_EQ(canonical_point_text({{"arena.topology", "walls"}}), "arena.topology=walls\n");
}

}  // namespace
}  // namespace swarmagg
