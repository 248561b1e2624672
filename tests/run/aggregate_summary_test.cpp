#include "run/aggregate_summary.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "config/world_loader.hpp"
#include "observers/observer_scene.hpp"
#include "run/replicate.hpp"
#include "run/run_folder.hpp"

namespace swarmagg {
namespace {

WorldSpec full_model_world(int record_every) {
  return load_world_text(R"(
name: leaving
arena: {width: 60, height: 60}
robots: {count: 40}
controller: {type: bayindir, p_leave: 0.005, leave_timeout: 5}
run: {duration: 150, replicates: 3, seed: 5, record_every: )" +
                             std::to_string(record_every) + "}\n",
                         "test");
}

void expect_aggregate_entries(const nlohmann::json& j, const std::string& where) {
  for (const char* key : {"leave_attempts", "escapes"}) {
    for (const char* part : {"rim", "inside", "total"})
      EXPECT_TRUE(j[key].contains(part)) << where << " " << key << "." << part;
    EXPECT_EQ(j[key]["total"].get<std::int64_t>(),
              j[key]["rim"].get<std::int64_t>() + j[key]["inside"].get<std::int64_t>());
  }
  EXPECT_TRUE(j["final"].contains("mean_member_spacing")) << where;
  ASSERT_TRUE(j["aggregates_by_size"].is_array()) << where;
  for (const auto& row : j["aggregates_by_size"]) {
    for (const char* key :
         {"size", "count", "mean_outer_radius", "mean_rim", "mean_member_spacing"})
      EXPECT_TRUE(row.contains(key)) << where << " aggregates_by_size." << key;
  }
  ASSERT_TRUE(j["leave_by_size"].is_array()) << where;
  EXPECT_FALSE(j["leave_by_size"].empty()) << where;
  for (const auto& row : j["leave_by_size"]) {
    for (const char* key : {"size", "attempts", "escapes", "aggregate_time"})
      EXPECT_TRUE(row.contains(key)) << where << " leave_by_size." << key;
  }
}

TEST(AggregateSummary, SummaryJsonHasTheEntriesPerReplicateAndPooled) {
  const WorldSpec spec = full_model_world(10);
  const RunResult result = run_world(spec, {});
  const nlohmann::json summary = run_summary(spec, result);
  expect_aggregate_entries(summary["pooled"], "pooled");
  std::int64_t attempts = 0, escapes = 0;
  for (const auto& replicate : summary["replicates"]) {
    expect_aggregate_entries(replicate, "replicate " + replicate["replicate"].dump());
    attempts += replicate["leave_attempts"]["total"].get<std::int64_t>();
    escapes += replicate["escapes"]["total"].get<std::int64_t>();
  }
  EXPECT_GT(attempts, 0);
  EXPECT_GT(escapes, 0);
  EXPECT_EQ(summary["pooled"]["leave_attempts"]["total"].get<std::int64_t>(), attempts);
  EXPECT_EQ(summary["pooled"]["escapes"]["total"].get<std::int64_t>(), escapes);
}

// The final aggregates' shapes list them in the tracker's order, as the sizes do.
TEST(AggregateSummary, FinalShapesMatchTheFinalSizes) {
  const RunResult result = run_world(full_model_world(10), {});
  for (const ReplicateOutcome& r : result.replicates) {
    ASSERT_EQ(r.final_aggregates.size(), r.final_aggregate_sizes.size());
    for (std::size_t k = 0; k < r.final_aggregates.size(); ++k) {
      EXPECT_EQ(r.final_aggregates[k].size, r.final_aggregate_sizes[k]);
      // Solid bodies never sink into each other (the invariant checker's test), but a leaver
      // passes through an agent that stopped waiting, and the two may pair up overlapping:
      // members are apart, not necessarily 2r apart.
      EXPECT_GT(r.final_aggregates[k].mean_member_spacing, 0.0);
      EXPECT_LE(r.final_aggregates[k].mean_member_spacing, 4.0 + 1e-9);  // linked within s
    }
  }
}

// The exposure counts each step's aggregates as the decision saw them: the state recorded
// after the step before. With every step recorded, it is the sum of NOA over all rows but
// the last; and attempts per size are bounded by size x exposure (each member may leave
// once per step).
TEST(AggregateSummary, ExposureIsTheNumberOfAggregatesAtEachDecision) {
  const WorldSpec spec = full_model_world(1);
  const RunResult result = run_world(spec, {});
  for (const ReplicateOutcome& r : result.replicates) {
    std::int64_t noa_sum = 0;
    for (std::size_t k = 0; k + 1 < r.rows.size(); ++k) noa_sum += r.rows[k].noa;
    std::int64_t exposure = 0;
    for (int m = 0; m <= r.leave.largest_size(); ++m) {
      const auto k = static_cast<std::size_t>(m);
      exposure += r.leave.aggregate_steps_by_size[k];
      EXPECT_LE(r.leave.attempts_by_size[k], m * r.leave.aggregate_steps_by_size[k]);
      EXPECT_LE(r.leave.escapes_by_size[k], r.leave.attempts_by_size[k]);
    }
    EXPECT_EQ(exposure, noa_sum);
  }
}

TEST(AggregateSummary, MeanMemberSpacingWeighsEveryMemberOnce) {
  std::vector<AggregateShape> shapes(2);
  shapes[0].size = 2;
  shapes[0].mean_member_spacing = 4.0;
  shapes[1].size = 6;
  shapes[1].mean_member_spacing = 2.0;
  EXPECT_DOUBLE_EQ(*mean_member_spacing(shapes), (2 * 4.0 + 6 * 2.0) / 8.0);
  EXPECT_FALSE(mean_member_spacing({}).has_value());
}

// A hand-placed 19-pack at 2r (centre, ring of 6, ring of 12, in that order) that leaves
// often: the first attempt of each seed is inside when the leaver is one of the inner
// seven, rim otherwise (docs/models.md: the outer ring has at most 4 fellows within 2.4).
WorldSpec packed_world(std::uint64_t seed) {
  testing::Scene scene;
  scene.add_hexagon(20.0, 20.0, 2, 2.0 + 1e-6);  // a hair apart: placed bodies never overlap
  std::ostringstream placement;
  placement.precision(17);
  for (std::size_t i = 0; i < scene.positions.size(); ++i) {
    placement << (i ? ", " : "") << "[" << scene.positions[i].x << ", " << scene.positions[i].y
              << ", 0]";
  }
  return load_world_text("name: pack\narena: {width: 40, height: 40}\nrobots: {placement: [" +
                             placement.str() +
                             "]}\ncontroller: {type: bayindir, p_leave: 0.002, leave_timeout: "
                             "5}\nrun: {duration: 100, replicates: 1, seed: " +
                             std::to_string(seed) + "}\n",
                         "pack");
}

TEST(AggregateSummary, APackedAggregateSplitsItsAttemptsIntoInsideAndRim) {
  int inside_seen = 0, rim_seen = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const WorldSpec world = packed_world(seed);
    Replicate replicate(world, 0);
    while (replicate.leave_episodes().tally().attempts.total() == 0 &&
           replicate.steps_done() < replicate.spec().steps())
      replicate.step();
    const LeaveTally& t = replicate.leave_episodes().tally();
    if (t.attempts.total() != 1) continue;  // none, or two in one step: not clean
    ASSERT_EQ(t.attempts_by_size[19], 1) << "seed " << seed;
    int leaver = -1;
    for (std::size_t i = 0; i < replicate.swarm().size(); ++i)
      if (replicate.swarm().state[i] == AgentState::Leave) leaver = static_cast<int>(i);
    ASSERT_GE(leaver, 0);
    const bool inner = leaver < 7;
    EXPECT_EQ(t.attempts.inside, inner ? 1 : 0) << "seed " << seed << ", agent " << leaver;
    EXPECT_EQ(t.attempts.rim, inner ? 0 : 1) << "seed " << seed << ", agent " << leaver;
    (inner ? inside_seen : rim_seen) += 1;
  }
  EXPECT_GT(inside_seen, 0);
  EXPECT_GT(rim_seen, 0);
}

}  // namespace
}  // namespace swarmagg
