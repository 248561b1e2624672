// The view's session without a window: it steps exactly as a batch run does, and its panel
// records (state times, transitions, NOA, trails) follow the replicate.
#include "view/view_session.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "config/world_loader.hpp"
#include "core/errors.hpp"
#include "run/placement_sample.hpp"
#include "run/state_hash.hpp"
#include "run/world_runner.hpp"

namespace swarmagg {
namespace {

WorldSpec demo(const std::string& engine, double duration = 600) {
  return load_world(
      std::string(SWARMAGG_SOURCE_DIR) + "/worlds/examples/demo.yaml",
      {"engine.type=" + engine, "run.duration=" + std::to_string(duration), "run.replicates=2"});
}

class ViewSessionEngines : public ::testing::TestWithParam<std::string> {};

TEST_P(ViewSessionEngines, StepsToTheStateOfABatchRunOfThatLength) {
  const WorldSpec run_spec = demo(GetParam(), 12.0);  // 120 steps
  const ReplicateOutcome batch = run_replicate(run_spec, 1, nullptr);
  std::ostringstream out;
  ViewSession session(demo(GetParam()), 1, out);
  ViewCommand select = view_command(ViewAction::Select, 5);
  session.apply(select);
  session.apply(overlay_command(Overlay::Trails, true));
  session.apply(view_command(ViewAction::Step, 100));
  session.apply(view_command(ViewAction::Step, 20));
  session.apply(view_command(ViewAction::Hash));
  EXPECT_EQ(out.str(), "state-hash " + state_hash_text(batch.final_state_hash) + " step 120\n");
  EXPECT_EQ(batch.final_state_hash, state_hash(session.replicate()));
}

INSTANTIATE_TEST_SUITE_P(BothEngines, ViewSessionEngines, ::testing::Values("kinematic", "box2d"));

TEST(ViewSession, ResetRepeatsAndReseedChangesTheRun) {
  std::ostringstream out;
  ViewSession session(demo("kinematic"), 0, out);
  session.step(30);
  const std::string first = session.hash_line();
  session.apply(view_command(ViewAction::Reset));
  EXPECT_EQ(session.replicate().steps_done(), 0);
  session.step(30);
  EXPECT_EQ(session.hash_line(), first);
  session.apply(view_command(ViewAction::Reseed));
  session.step(30);
  EXPECT_NE(session.hash_line(), first);
  EXPECT_EQ(session.spec().run.seed, demo("kinematic").run.seed + 1);
}

TEST(ViewSession, PlayingStopsAtTheDurationAndPrintsTheSummaryLine) {
  std::ostringstream out;
  ViewSession session(demo("kinematic", 2.0), 0, out);  // 20 steps
  session.apply(view_command(ViewAction::Speed, 8));
  session.apply(view_command(ViewAction::Play));
  for (int frame = 0; frame < 5; ++frame) session.advance_frame(0.016, 1.0);
  EXPECT_EQ(session.replicate().steps_done(), 20);
  EXPECT_FALSE(session.control().playing());
  EXPECT_EQ(out.str().rfind("demo: 1 replicate x 20 steps in ", 0), 0u) << out.str();
  EXPECT_NE(out.str().find("mean final NOA"), std::string::npos);
}

TEST(ViewSession, DetailsFollowTheAgent) {
  std::ostringstream out;
  ViewSession session(demo("kinematic"), 0, out);
  EXPECT_FALSE(session.details(-1));
  EXPECT_FALSE(session.details(60));
  EXPECT_THROW(session.apply(view_command(ViewAction::Select, 60)), InputError);
  session.step(3000);
  bool saw_transition = false;
  bool saw_aggregate = false;
  for (std::int32_t i = 0; i < 60; ++i) {
    const auto d = session.details(i);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->state, session.replicate().swarm().state[i]);
    EXPECT_LE(d->time_in_state, session.replicate().time() + 1e-9);
    for (const std::uint32_t n : d->neighbours) {
      EXPECT_LE(
          session.spec().arena.geometry().distance(session.replicate().engine().positions()[i],
                                                   session.replicate().engine().positions()[n]),
          session.spec().robots.detection_radius + 1e-9);
    }
    if (d->last_transition) {
      saw_transition = true;
      EXPECT_EQ(d->last_transition->to, d->state);
      EXPECT_NEAR(d->time_in_state,
                  (session.replicate().steps_done() - d->last_transition->step) * 0.1, 1e-9);
    }
    if (d->aggregate >= 0) {
      saw_aggregate = true;
      EXPECT_GE(d->aggregate_size, 2);
      EXPECT_EQ(d->state, AgentState::Wait);
    }
  }
  EXPECT_TRUE(saw_transition);
  EXPECT_TRUE(saw_aggregate);
  // NOA every record_every (10) steps, and the model's curve for this Bayindir world.
  EXPECT_EQ(session.noa_history().size(), 3000u / 10 + 1);
  EXPECT_FALSE(session.model_noa().empty());
}

// The window draws the world's chosen expected variant, as `model` writes it (computed
// without the other variants or the noise floors).
TEST(ViewSession, TheModelCurveIsTheChosenVariantsExpectedNoa) {
  const WorldSpec spec = demo("kinematic");
  std::ostringstream out;
  const ViewSession session(spec, 0, out);
  WorldSpec expected = spec;
  expected.model.stochastic_replicates = 0;
  const std::vector<VariantPrediction> predictions = predict_world(expected, nullptr, 0);
  const auto chosen = std::find_if(predictions.begin(), predictions.end(),
                                   [](const VariantPrediction& p) { return p.chosen; });
  ASSERT_NE(chosen, predictions.end());
  ASSERT_EQ(session.model_noa().size(), chosen->series.size());
  for (std::size_t i = 0; i < chosen->series.size(); ++i) {
    EXPECT_EQ(session.model_noa()[i].time,
              static_cast<double>(chosen->series[i].step) * spec.engine.dt);
    EXPECT_EQ(session.model_noa()[i].noa, *chosen->series[i].noa);
  }
}

TEST(ViewSession, TrailsKeepTheLastPositions) {
  std::ostringstream out;
  ViewSession session(demo("kinematic"), 0, out);
  EXPECT_EQ(session.extras().trail_frames, 0);
  session.apply(overlay_command(Overlay::Trails, true));
  session.step(10 * (kTrailFrames + 5));  // one frame per tu (10 steps)
  EXPECT_EQ(session.extras().trail_frames, kTrailFrames);
  EXPECT_EQ(session.extras().trail.size(), 60u * kTrailFrames);
  const Vec2 last = session.extras().trail[(kTrailFrames - 1) * 60 + 7];
  EXPECT_EQ(last, session.replicate().engine().positions()[7]);
  session.apply(overlay_command(Overlay::Trails, false));
  EXPECT_EQ(session.extras().trail_frames, 0);
}

TEST(ViewSession, RefusesAReplicateTheWorldDoesNotHave) {
  std::ostringstream out;
  EXPECT_THROW(ViewSession(demo("kinematic"), 2, out), InputError);
}

}  // namespace
}  // namespace swarmagg
