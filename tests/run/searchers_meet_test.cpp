// A searcher that halts at s from a waiting agent meets it: the waiting agent, if it was
// closing up (compaction), halted there too and stands while the searcher joins, so the two
// stay within s (docs/controllers.md, "A meeting stops both sides"). Before, the member crept
// on after the searcher's halt, ended the step just beyond s, and the searcher, seeing nobody
// within s, approached again, halted again, and so on for thousands of steps: in the paper's
// 10-agent Soysal world 10,654 of the first 2 x 10^5 steps had such a stalker, each counting
// an encounter.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <vector>

#include "config/world_loader.hpp"
#include "geometry/arena_geometry.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

bool searching(AgentState state) {
  return state == AgentState::Go || state == AgentState::Approach;
}

struct MeetingFaults {
  // Steps at whose end a searcher stood just beyond s (within 0.1 % of it) from the nearest
  // waiting agent, as it had at the end of the step before.
  std::int64_t stalking_steps = 0;
  // Searchers that joined and searched again within 5 steps (left alone beyond s).
  std::int64_t quick_resumes = 0;
};

MeetingFaults meeting_faults(const WorldSpec& world, std::int64_t steps) {
  Replicate replicate(world, 0);
  const ArenaGeometry arena = world.arena.geometry();
  const double s = world.robots.detection_radius;
  const std::size_t n = static_cast<std::size_t>(world.robots.count);
  std::vector<std::uint8_t> was_at_rim(n, 0);
  std::vector<AgentState> before(replicate.swarm().state.begin(), replicate.swarm().state.end());
  std::vector<std::int64_t> joined_at(n, -100);
  MeetingFaults faults;
  for (std::int64_t step = 0; step < steps; ++step) {
    replicate.step();
    const auto positions = replicate.engine().positions();
    const auto& states = replicate.swarm().state;
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (searching(before[i]) && states[i] == AgentState::Wait) joined_at[i] = step;
      if (before[i] == AgentState::Wait && searching(states[i]) && step - joined_at[i] <= 5)
        ++faults.quick_resumes;
      before[i] = states[i];
      bool at_rim = false;
      if (searching(states[i])) {
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < n; ++j) {
          if (states[j] != AgentState::Wait) continue;
          nearest = std::min(nearest, norm(arena.displacement(positions[i], positions[j])));
        }
        at_rim = nearest > s && nearest <= s * (1.0 + 1e-3);
      }
      any |= at_rim && was_at_rim[i];
      was_at_rim[i] = at_rim;
    }
    faults.stalking_steps += any;
  }
  return faults;
}

TEST(SearchersMeet, NoSearcherStalksOrLosesAClosingMemberInThePaperSoysalWorld) {
  const WorldSpec world = load_world(SWARMAGG_SOURCE_DIR "/worlds/paper/soysal-10-constant.yaml");
  const MeetingFaults faults = meeting_faults(world, 200000);
  EXPECT_EQ(faults.stalking_steps, 0);
  EXPECT_EQ(faults.quick_resumes, 0);
}

}  // namespace
}  // namespace swarmagg
