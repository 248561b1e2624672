// Packed aggregates come to rest: no agent moves by less than positions can resolve. Such a
// move, rounded to the grid of doubles, becomes one ulp along an axis, which can point into a
// body the agent already touches; the agent then sinks by an ulp a step and keeps its whole
// aggregate awake (and costing a full step) for ever.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "geometry/arena_geometry.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// The compaction example made dense and without leaving: its aggregates pack and stay.
WorldSpec packed_world(int seed) {
  return load_world("worlds/examples/compact.yaml",
                    {"robots.count=2000", "arena.width=144", "arena.height=144",
                     "controller.p_leave=0", "run.seed=" + std::to_string(seed)});
}

TEST(RestResolution, NoAgentMovesByLessThanPositionsResolve) {
  const WorldSpec spec = packed_world(0);
  const ArenaGeometry arena = spec.arena.geometry();
  const double resolution = arena.position_resolution();
  Replicate replicate(spec, 0);
  std::vector<Vec2> before(replicate.engine().positions().begin(),
                           replicate.engine().positions().end());
  // The engine that rounded such moves made the first within ten steps, as the agents close up.
  for (int step = 0; step < 300; ++step) {
    replicate.step();
    const auto after = replicate.engine().positions();
    for (std::size_t agent = 0; agent < after.size(); ++agent) {
      const double moved = arena.distance(before[agent], after[agent]);
      ASSERT_TRUE(moved == 0.0 || moved >= resolution)
          << "agent " << agent << " moved by " << moved << " in step " << step + 1
          << ", below the positions' resolution " << resolution;
      before[agent] = after[agent];
    }
  }
}

// Every agent waits by step 250 and the world is one island of contacts; it sleeps whole
// from about step 1,250. With sub-resolution moves rounded, three agents crept by an ulp a
// step from then on and the world never slept.
TEST(RestResolution, ADenseWorldOfWaitingAgentsFallsAsleepWholeAndStays) {
  const WorldSpec spec = packed_world(0);
  Replicate replicate(spec, 0);
  for (int step = 0; step < 1500; ++step) replicate.step();
  for (int step = 1500; step < 2000; ++step) {
    replicate.step();
    ASSERT_EQ(replicate.engine().asleep_count(), 2000u) << "step " << step + 1;
  }
}

// Two searchers meant to halt on each other, in an arena so vast that 10^-12 of its side is
// more than the hair a perceiving halt stops inside s: their last moves are below that and were
// dropped, and the pair stood just outside s for ever, meeting anew every step (NOA 0, 45
// encounters in 50 steps). Dropped moves are now also held below a quarter of that hair.
TEST(RestResolution, TwoSearchersMeetInAVastArena) {
  for (const char* side : {"5000", "1000000"}) {
    std::string text = "name: vast\narena: {width: ";
    text += side;
    text += ", height: ";
    text += side;
    text += R"(, topology: torus}
robots:
  placement: [[100, 20, 0], [105.000000005, 20, 180]]
controller: {type: bayindir, p_leave: 0.0}
run: {duration: 5}
)";
    const WorldSpec spec = load_world_text(text, "vast");
    Replicate replicate(spec, 0);
    replicate.set_checking(true);
    for (int step = 0; step < 50; ++step) replicate.step();
    EXPECT_EQ(replicate.aggregates().count(), 1) << side;
    EXPECT_EQ(replicate.events().encounters, 1u) << side;
  }
}

}  // namespace
}  // namespace swarmagg
