#include "run/world_runner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "config/world_loader.hpp"
#include "geometry/arena_geometry.hpp"
#include "output/timeseries_csv.hpp"
#include "run/initial_placement.hpp"
#include "run/replicate.hpp"
#include "run/run_folder.hpp"
#include "testing/scratch_dir.hpp"

namespace swarmagg {
namespace {

WorldSpec full_model_world() {
  return load_world_text(R"(
name: determinism
arena: {width: 80, height: 80}
robots: {count: 40}
controller: {type: bayindir, p_leave: 0.005, leave_timeout: 5}
run: {duration: 150, replicates: 4, seed: 5, record_every: 7}
)",
                         "test");
}

std::string csv_of(const RunResult& result) {
  return timeseries_csv(all_rows(result));
}

RunResult run_with_threads(const WorldSpec& spec, int threads) {
  RunOptions options;
  options.threads = threads;
  return run_world(spec, options);
}

TEST(WorldRunner, SameSeedGivesIdenticalOutput) {
  const WorldSpec spec = full_model_world();
  EXPECT_EQ(csv_of(run_with_threads(spec, 1)), csv_of(run_with_threads(spec, 1)));
}

TEST(WorldRunner, ThreadCountDoesNotChangeTheOutput) {
  const WorldSpec spec = full_model_world();
  const RunResult one = run_with_threads(spec, 1);
  const RunResult two = run_with_threads(spec, 2);
  EXPECT_EQ(two.threads, 2);
  EXPECT_EQ(csv_of(one), csv_of(two));
}

TEST(WorldRunner, ThreadsBeyondTheReplicatesGoIntoTheSteps) {
  WorldSpec spec = full_model_world();
  spec.run.replicates = 1;
  EXPECT_EQ(plan_threads(spec, 4).replicates_at_once, 1);
  EXPECT_EQ(plan_threads(spec, 4).step_threads, 4);
  spec.run.replicates = 2;
  EXPECT_EQ(plan_threads(spec, 5).replicates_at_once, 2);
  EXPECT_EQ(plan_threads(spec, 5).step_threads, 2);
  spec.run.replicates = 10;
  EXPECT_EQ(plan_threads(spec, 3).replicates_at_once, 3);
  EXPECT_EQ(plan_threads(spec, 3).step_threads, 1);
  spec.run.threads = 2;
  EXPECT_EQ(plan_threads(spec, 0).replicates_at_once, 2) << "0 falls back to run.threads";
  // Box2D steps a world on one thread: summary.json and the run's line say so.
  spec.engine.type = EngineType::Box2D;
  spec.run.replicates = 1;
  EXPECT_EQ(plan_threads(spec, 4).step_threads, 1);
}

// One large replicate: `--threads` splits its steps, and the output stays the same.
TEST(WorldRunner, OneLargeReplicateGivesTheSameOutputOnSeveralThreads) {
  WorldSpec spec = full_model_world();
  spec.robots.count = 40000;
  spec.arena.width = spec.arena.height = 2000.0;
  spec.run.replicates = 1;
  spec.run.duration = 3.0;
  spec.run.record_every = 1;
  const RunResult one = run_with_threads(spec, 1);
  const RunResult three = run_with_threads(spec, 3);
  EXPECT_EQ(three.step_threads, 3);
  EXPECT_EQ(csv_of(one), csv_of(three));
}

// Partitions are recorded where the partition model can hold them (30 agents); a larger
// swarm's record grew with every step it ran, one part per agent, and no model read it.
TEST(WorldRunner, PartitionsAreRecordedForSoysalWorldsTheModelCanHold) {
  const testing::ScratchDir scratch("partitions");
  for (const int agents : {30, 31}) {
    const WorldSpec spec = load_world_text(
        "arena: {width: 100, height: 100}\nrobots: {count: " + std::to_string(agents) +
            "}\ncontroller: {type: soysal}\n"
            "run: {duration: 20, replicates: 1}\n",
        "t");
    const RunResult result = run_world(spec, RunOptions{});
    const auto folder = scratch.path() / std::to_string(agents);
    write_run_folder(spec, result, folder, {});
    EXPECT_EQ(result.replicates.front().partition_steps.empty(), agents > 30) << agents;
    EXPECT_EQ(std::filesystem::exists(folder / "partitions.csv"), agents <= 30) << agents;
  }
}

TEST(WorldRunner, AnotherSeedGivesAnotherRun) {
  WorldSpec spec = full_model_world();
  const std::string first = csv_of(run_with_threads(spec, 2));
  spec.run.seed = 6;
  EXPECT_NE(first, csv_of(run_with_threads(spec, 2)));
}

TEST(WorldRunner, TheFullModelCreatesGrowsDissolvesAndShrinks) {
  const RunResult result = run_with_threads(full_model_world(), 2);
  EventCounts total;
  for (const ReplicateOutcome& r : result.replicates) {
    const TimeseriesRow& last = r.rows.back();
    EXPECT_EQ(last.step, 1500);
    EXPECT_EQ(last.states.searching + last.states.waiting + last.states.leaving, 40);
    total.creations += last.events.creations;
    total.growths += last.events.growths;
    total.dissipations += last.events.dissipations;
    total.shrinks += last.events.shrinks;
  }
  EXPECT_GT(total.creations, 0u);
  EXPECT_GT(total.growths, 0u);
  EXPECT_GT(total.dissipations, 0u);
  EXPECT_GT(total.shrinks, 0u);
}

TEST(InitialPlacement, RandomBodiesNeverOverlap) {
  WorldSpec spec = load_world_text("arena: {width: 60, height: 60}\nrobots: {count: 400}\n", "t");
  const InitialPlacement placed = place_agents(spec, CounterRng::for_replicate(1, 0));
  const ArenaGeometry arena = spec.arena.geometry();
  ASSERT_EQ(placed.positions.size(), 400u);
  for (std::size_t i = 0; i < placed.positions.size(); ++i) {
    EXPECT_GE(placed.positions[i].x, 0.0);
    EXPECT_LT(placed.positions[i].x, 60.0);
    for (std::size_t j = i + 1; j < placed.positions.size(); ++j) {
      ASSERT_GE(arena.distance(placed.positions[i], placed.positions[j]), 2.0);
    }
  }
}

// Large swarms are numbered along space, so that a range of ids lies in a compact patch of
// the arena; small ones keep the draw order. The median, over the blocks of `block`
// consecutive ids, of the longer side of the box around a block's positions.
double median_block_width(const std::vector<Vec2>& positions, std::size_t block) {
  std::vector<double> widths;
  for (std::size_t first = 0; first + block <= positions.size(); first += block) {
    Vec2 low = positions[first], high = positions[first];
    for (std::size_t i = first; i < first + block; ++i) {
      low = {std::min(low.x, positions[i].x), std::min(low.y, positions[i].y)};
      high = {std::max(high.x, positions[i].x), std::max(high.y, positions[i].y)};
    }
    widths.push_back(std::max(high.x - low.x, high.y - low.y));
  }
  std::nth_element(widths.begin(), widths.begin() + widths.size() / 2, widths.end());
  return widths[widths.size() / 2];
}

// On a torus the far edge is the near edge: an agent given at x = width starts at x = 0 on both
// engines (the kinematic engine recorded x = width until the agent moved).
TEST(InitialPlacement, AGivenPositionOnTheTorusFarEdgeStartsOnItsNearEdge) {
  const WorldSpec torus = load_world_text(
      "arena: {width: 20, height: 20}\nrobots: {placement: [[20, 20, 0], [17.5, 20, 0]]}\n", "t");
  const InitialPlacement placed = place_agents(torus, CounterRng::for_replicate(1, 0));
  EXPECT_EQ(placed.positions[0], (Vec2{0.0, 0.0}));
  EXPECT_EQ(placed.positions[1], (Vec2{17.5, 0.0}));
  for (const char* engine : {"kinematic", "box2d"}) {
    WorldSpec spec = torus;
    spec.engine.type = std::string(engine) == "box2d" ? EngineType::Box2D : EngineType::Kinematic;
    const Replicate replicate(spec, 0);
    EXPECT_EQ(replicate.engine().positions()[0], (Vec2{0.0, 0.0})) << engine;
  }
}

TEST(InitialPlacement, LargeSwarmsAreNumberedAlongSpaceSmallOnesByDraw) {
  WorldSpec large =
      load_world_text("arena: {width: 1500, height: 1500}\nrobots: {count: 10000}\n", "t");
  const InitialPlacement placed = place_agents(large, CounterRng::for_replicate(1, 0));
  ASSERT_EQ(placed.positions.size(), 10000u);
  // 250 agents cover about 240 x 240 of this arena; numbered along rows of it (or bands, the
  // order before) they would stretch over its whole width.
  EXPECT_LT(median_block_width(placed.positions, 250), 600.0);
  WorldSpec small = large;
  small.robots.count = 4000;
  const InitialPlacement drawn = place_agents(small, CounterRng::for_replicate(1, 0));
  EXPECT_GT(median_block_width(drawn.positions, 250), 1400.0);
  // The numbering only permutes: the first 4000 draws are the same positions either way
  // (both runs draw agent i's position from the same counter), so every small-swarm
  // position appears in the large swarm.
  std::vector<Vec2> sorted_large = placed.positions;
  auto by_xy = [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::sort(sorted_large.begin(), sorted_large.end(), by_xy);
  for (const Vec2& p : drawn.positions) {
    EXPECT_TRUE(std::binary_search(sorted_large.begin(), sorted_large.end(), p, by_xy));
  }
}

// In ghost mode agents are an ideal 2D gas: each pair meets at rate 2 s <|w|> / A with
// mean relative speed <|w|> = 4 v / pi, so Z = (4/pi) s v N (N-1) / A per tu. Encounter
// counts are close to Poisson, so 5 standard errors (sqrt of the count) bound the noise:
// the test fails by chance less than once in a million runs.
TEST(WorldRunner, GhostEncounterRateMatchesKineticTheory) {
  const WorldSpec spec = load_world_text(R"(
arena: {width: 200, height: 200}
robots: {count: 100, speed: 1.5}
controller: {type: collision, collision_mode: ghost, tumble: 0.001}
run: {duration: 1500, replicates: 6, seed: 3, record_every: 1000}
)",
                                         "test");
  const RunResult result = run_with_threads(spec, 2);
  double encounters = 0.0;
  for (const ReplicateOutcome& r : result.replicates) encounters += r.rows.back().events.encounters;
  const double n = 100.0;
  const double expected = 4.0 / M_PI * 4.0 * 1.5 * n * (n - 1.0) / (200.0 * 200.0) *
                          spec.run.duration * spec.run.replicates;
  EXPECT_NEAR(encounters, expected, 5.0 * std::sqrt(expected))
      << "measured " << encounters << ", kinetic theory " << expected;
}

TEST(RunFolder, WritesEveryOutputAndAResolvedWorldThatLoadsBack) {
  WorldSpec spec = full_model_world();
  spec.run.replicates = 2;
  const testing::ScratchDir scratch("run-folder-test");
  const auto& out = scratch.path();
  const RunResult result = run_with_threads(spec, 2);
  write_run_folder(spec, result, out);
  for (const char* file : {"timeseries.csv", "summary.json", "world.resolved.yaml"}) {
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  }
  // How it ran: replicates side by side, and threads within each replicate's step.
  nlohmann::json summary;
  std::ifstream(out / "summary.json") >> summary;
  EXPECT_EQ(summary["threads"], result.threads);
  EXPECT_EQ(summary["step_threads"], result.step_threads);
  const WorldSpec again = load_world((out / "world.resolved.yaml").string());
  EXPECT_EQ(again.run.seed, spec.run.seed);
  EXPECT_EQ(again.robots.count, spec.robots.count);
  std::ifstream csv(out / "timeseries.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, kTimeseriesHeader);
  for (const auto& entry : std::filesystem::directory_iterator(out)) {
    EXPECT_EQ(entry.path().extension(),
              entry.path().extension() == ".tmp" ? ".none" : entry.path().extension());
  }
}

}  // namespace
}  // namespace swarmagg
