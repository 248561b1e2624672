// The hot path allocates nothing per step once warmed up (issue 8): every buffer a step
// needs is kept and reused, so the allocator never serialises the step threads or the
// replicates running beside them. Each case builds a replicate, warms it up, then counts
// every allocation (all threads, operator new and malloc; allocation_counter.hpp) over the
// next steps, which do what run_replicate does per step: the step itself (controller,
// engine, aggregate tracker), a recorded time-series row (into a vector reserved up front,
// as run_replicate does) and, for Soysal, the partition tracker, counted apart: it must
// allocate only for a partition the swarm enters for the first time (a new map entry).
//
// Warm-up: buffers sized by the number of close pairs grow geometrically while aggregates
// form and densify, a handful of times per run (Bayindir, N = 150, seed 8: nine times in
// the first 75 steps, then at steps 302, 400, 922, 1020, 1325, 2034, 2253 and 11085 of
// 30,000; Soysal: steps 8994 and 17177 after the first 61). That is growth to a high-water
// mark, not an allocation per step, so aggregating worlds are measured after their
// aggregates have formed; the ghost world is stationary.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "alloc/allocation_counter.hpp"
#include "config/world_loader.hpp"
#include "observers/partition_tracker.hpp"
#include "observers/timeseries_row.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

using testing::allocation_counts;
using testing::AllocationCounts;

constexpr int kWarmUpSteps = 300;
constexpr int kAggregatingWarmUpSteps = 12000;
constexpr int kMeasuredSteps = 1000;

struct Case {
  std::string name;
  std::string controller = "collision";
  int agents = 150;
  int threads = 1;
  EngineType engine = EngineType::Kinematic;
  int warm_up = kWarmUpSteps;
  int measured = kMeasuredSteps;
};

void PrintTo(const Case& c, std::ostream* out) {
  *out << c.name;
}

// The paper's density (150 agents on 180 x 180) for any agent count, with the default
// robots (r = 1, s = 4, v = 1, dt = 0.1) and each controller's paper parameters.
WorldSpec world_for(const Case& c) {
  WorldSpec spec;
  spec.name = c.name;
  spec.source = "step_allocation_test";
  const double side = 180.0 * std::sqrt(c.agents / 150.0);
  spec.arena = {side, side, Topology::Torus};
  spec.robots.count = c.agents;
  spec.controller.type = c.controller;
  if (c.controller == "collision") {
    spec.controller.collision_mode = CollisionMode::Ghost;
    spec.controller.tumble = 0.001;
  }
  if (c.controller == "bayindir") spec.controller.p_leave = 0.001;
  spec.engine.type = c.engine;
  spec.run.replicates = 1;
  spec.run.seed = 8;
  check_world(spec);
  return spec;
}

struct Measured {
  AllocationCounts step;        // the step and the recorded row
  AllocationCounts partitions;  // Soysal's partition tracker
  std::size_t new_partitions = 0;
  std::string activity;  // what happened meanwhile, to show the steps did real work
};

// One replicate stepped as run_replicate steps it.
class SteppedReplicate {
 public:
  SteppedReplicate(const WorldSpec& spec, int threads, int steps)
      : replicate_(spec, 0), partitions_(controller_rules(spec).records_partitions) {
    replicate_.set_threads(threads);
    replicate_.set_checking(false);  // the invariant checks are a debugging aid, not the step
    rows_.reserve(static_cast<std::size_t>(steps));
  }

  void steps(int count, Measured& measured) {
    const int n = static_cast<int>(replicate_.swarm().size());
    for (int k = 0; k < count; ++k) {
      const AllocationCounts start = allocation_counts();
      replicate_.step();
      rows_.push_back(observe_row(replicate_.index(), replicate_.snapshot(),
                                  replicate_.aggregates(), replicate_.events()));
      const AllocationCounts stepped = allocation_counts();
      measured.step = measured.step + (stepped - start);
      if (partitions_) {
        partition_tracker_.observe(replicate_.aggregates(), n);
        measured.partitions = measured.partitions + (allocation_counts() - stepped);
      }
    }
  }

  const Replicate& replicate() const { return replicate_; }
  std::size_t partitions_seen() const { return partition_tracker_.steps_by_partition().size(); }

 private:
  Replicate replicate_;
  bool partitions_;
  PartitionTracker partition_tracker_;
  std::vector<TimeseriesRow> rows_;
};

Measured allocations_after_warm_up(const Case& c) {
  const WorldSpec spec = world_for(c);
  SteppedReplicate stepped(spec, c.threads, c.warm_up + c.measured);
  Measured ignored;
  stepped.steps(c.warm_up, ignored);
  const EventCounts before = stepped.replicate().events();
  const std::size_t partitions_before = stepped.partitions_seen();
  Measured measured;
  stepped.steps(c.measured, measured);
  measured.new_partitions = stepped.partitions_seen() - partitions_before;
  const EventCounts& after = stepped.replicate().events();
  measured.activity = "encounters " + std::to_string(after.encounters - before.encounters) +
                      ", creations " + std::to_string(after.creations - before.creations) +
                      ", growths " + std::to_string(after.growths - before.growths) +
                      ", dissipations " + std::to_string(after.dissipations - before.dissipations) +
                      ", shrinks " + std::to_string(after.shrinks - before.shrinks) +
                      ", new partitions " + std::to_string(measured.new_partitions);
  return measured;
}

std::string describe(const Case& c, const AllocationCounts& counts) {
  char line[256];
  std::snprintf(
      line, sizeof line,
      "%s: %d agents, %d thread(s), steps %d..%d: %llu operator new, %llu delete, %s",
      c.name.c_str(), c.agents, c.threads, c.warm_up, c.warm_up + c.measured,
      static_cast<unsigned long long>(counts.news), static_cast<unsigned long long>(counts.deletes),
      testing::counts_mallocs() ? (std::to_string(counts.mallocs) + " malloc-family calls").c_str()
                                : "malloc not counted in this build");
  return line;
}

class KinematicStep : public ::testing::TestWithParam<Case> {};

TEST_P(KinematicStep, AllocatesNothingAfterWarmUp) {
  const Case& c = GetParam();
  const Measured m = allocations_after_warm_up(c);
  std::printf("%s\n  (%s)\n", describe(c, m.step).c_str(), m.activity.c_str());
  EXPECT_EQ(m.step.news, 0u) << describe(c, m.step);
  EXPECT_EQ(m.step.deletes, 0u) << describe(c, m.step);
  EXPECT_EQ(m.step.mallocs, 0u) << describe(c, m.step);
  // A new partition costs its map node and its key (longer than a short string).
  EXPECT_LE(m.partitions.news, 2 * m.new_partitions) << describe(c, m.partitions);
  EXPECT_EQ(m.partitions.deletes, 0u) << describe(c, m.partitions);
}

std::vector<Case> kinematic_cases() {
  std::vector<Case> cases;
  const std::pair<const char*, const char*> controllers[] = {
      {"ghost", "collision"}, {"bayindir", "bayindir"}, {"soysal", "soysal"}};
  for (const auto& [name, type] : controllers) {
    for (const int threads : {1, 2}) {
      Case c;
      c.name = std::string(name) + "_" + std::to_string(threads) + "_threads";
      c.controller = type;
      c.threads = threads;
      if (std::string(type) != "collision") c.warm_up = kAggregatingWarmUpSteps;
      cases.push_back(c);
    }
  }
  // Large enough that two threads share the neighbour search and the strip sort
  // (16,384 agents per task); fewer steps, to keep the test quick. Bayindir's buffers grew
  // at steps 97 and 250 here (seeds 8 and 9 alike) while waiting agents stood still; with
  // compaction (docs/controllers.md) closing aggregates add close pairs, and steps 100-200 saw
  // buffers grow: the window is taken after the packs have formed (400-500, measured clean).
  for (const auto& [name, type] : {controllers[0], controllers[1]}) {
    Case c;
    c.name = std::string(name) + "_40000_agents_2_threads";
    c.controller = type;
    c.agents = 40000;
    c.threads = 2;
    c.warm_up = 400;
    c.measured = 100;
    cases.push_back(c);
  }
  // From 2^18 agents the guarded motion orders its events by island (guarded_motion.hpp),
  // with buffers of its own.
  Case islands;
  islands.name = "bayindir_270000_agents_2_threads";
  islands.controller = "bayindir";
  islands.agents = 270000;
  islands.threads = 2;
  islands.warm_up = 400;
  islands.measured = 50;
  cases.push_back(islands);
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Worlds, KinematicStep, ::testing::ValuesIn(kinematic_cases()),
                         [](const auto& info) { return info.param.name; });

// Box2D may allocate inside its own step by design (contacts come from its block allocator,
// which grows in chunks; its stack allocator falls back to malloc for large islands), so
// its malloc calls are only reported. Our code around it (operator new: Box2D itself uses
// malloc) may grow a buffer now and then, but must not allocate step after step.
TEST(Box2DStep, ReportsItsAllocationsAfterWarmUp) {
  for (const std::string type : {"collision", "bayindir"}) {
    Case c;
    c.name = type == "collision" ? "box2d_ghost" : "box2d_bayindir";
    c.controller = type;
    c.engine = EngineType::Box2D;
    const Measured m = allocations_after_warm_up(c);
    std::printf("%s\n  (%s)\n", describe(c, m.step).c_str(), m.activity.c_str());
    RecordProperty(c.name + "_news", std::to_string(m.step.news));
    RecordProperty(c.name + "_mallocs", std::to_string(m.step.mallocs));
    EXPECT_LT(m.step.news, static_cast<std::uint64_t>(c.measured / 10)) << describe(c, m.step);
  }
}

// The counter itself: a test that cannot see an allocation proves nothing.
TEST(AllocationCounter, CountsAnAllocationOnAnyPath) {
  const AllocationCounts start = allocation_counts();
  std::vector<double> v(1000, 1.0);
  asm volatile("" : : "g"(v.data()) : "memory");  // keep the allocation
  v.clear();
  v.shrink_to_fit();
  const AllocationCounts counts = allocation_counts() - start;
  EXPECT_EQ(counts.news, 1u);
  EXPECT_EQ(counts.deletes, 1u);
  if (testing::counts_mallocs()) {
    EXPECT_GE(counts.mallocs, 1u);
  }
}

}  // namespace
}  // namespace swarmagg
