// One replicate stepped with several threads must end bit-identical to the same replicate on
// one thread: the step threads split the moves, the strip sort and the pair search, and
// each must join its parts in a fixed order. The world is large enough that every threaded
// pass splits across two and across three threads: the moves take 65,536 agents per task
// (kinematic_engine.cpp), the strip sort and the pair search 16,384 (sorted_strips.cpp,
// neighbour_search.cpp), so N = 200,000 gives three move tasks with three threads. Ghosts
// stress the encounter counts, Bayindir's full model the guarded halts and every event.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <span>
#include <vector>

#include "bench/lib/paper_density_world.hpp"
#include "config/world_loader.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

constexpr int kAgents = 200000;
constexpr int kSteps = 25;

WorldSpec identity_world(const std::string& type) {
  WorldSpec spec = paper_density_world(kAgents, type);
  if (type == "collision") spec.controller.tumble = 0.001;
  spec.run.seed = 11;
  return spec;
}

// Everything a step leaves behind, copied out for comparison.
struct EndState {
  std::vector<Vec2> positions;
  SwarmState swarm;
  std::vector<std::int32_t> aggregate_of;
  EventCounts events;
};

EndState run(const WorldSpec& spec, int threads) {
  Replicate replicate(spec, 0);
  replicate.set_threads(threads);
  replicate.set_checking(false);
  for (int k = 0; k < kSteps; ++k) replicate.step();
  const auto positions = replicate.engine().positions();
  const auto aggregate_of = replicate.aggregates().aggregate_of();
  return {{positions.begin(), positions.end()},
          replicate.swarm(),
          {aggregate_of.begin(), aggregate_of.end()},
          replicate.events()};
}

// Bit for bit, not merely equal as numbers (== would take -0.0 for +0.0).
template <typename T, typename Allocator>
bool same_bits(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_identical(const EndState& one, const EndState& many, int threads) {
  SCOPED_TRACE(testing::Message() << threads << " threads against 1");
  EXPECT_TRUE(same_bits(one.positions, many.positions));
  EXPECT_TRUE(same_bits(one.swarm.state, many.swarm.state));
  EXPECT_TRUE(same_bits(one.swarm.heading, many.swarm.heading));
  EXPECT_TRUE(same_bits(one.swarm.leave_time_left, many.swarm.leave_time_left));
  EXPECT_TRUE(same_bits(one.swarm.partner, many.swarm.partner));
  EXPECT_TRUE(same_bits(one.aggregate_of, many.aggregate_of));
  EXPECT_EQ(one.events.encounters, many.events.encounters);
  EXPECT_EQ(one.events.creations, many.events.creations);
  EXPECT_EQ(one.events.growths, many.events.growths);
  EXPECT_EQ(one.events.dissipations, many.events.dissipations);
  EXPECT_EQ(one.events.shrinks, many.events.shrinks);
}

void check_thread_counts(const std::string& type) {
  const WorldSpec spec = identity_world(type);
  // Waiting agents move too (on by default, docs/controllers.md), through the same guarded solver.
  EXPECT_TRUE(spec.controller.compaction.enabled);
  const EndState one = run(spec, 1);
  // The comparison must see a world that did something.
  EXPECT_GT(one.events.encounters, 1000u);
  if (type == "bayindir") {
    EXPECT_GT(one.events.creations, 100u);
    EXPECT_GT(one.events.growths, 0u);
  }
  for (const int threads : {2, 3}) expect_identical(one, run(spec, threads), threads);
}

TEST(StepThreadsIdentity, GhostsEndBitIdenticalOnOneTwoAndThreeThreads) {
  check_thread_counts("collision");
}

TEST(StepThreadsIdentity, BayindirFullModelEndsBitIdenticalOnOneTwoAndThreeThreads) {
  check_thread_counts("bayindir");
}

}  // namespace
}  // namespace swarmagg
