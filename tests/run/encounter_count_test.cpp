// An encounter is a pair coming within the detection radius s. The kinematic engine halts a
// meeting pair on s (a hair inside); rounding could leave it an ulp outside, and compaction's
// next pull inwards then counted the same pair again: 11-27 % more encounters in the paper's
// compacting worlds, and `compare` called the engines' encounter rates different (kinematic
// 0.76, Box2D 0.66 per tu in creation-100). Counted from positions, entries into s between
// the ends of two steps, the two agree up to the pairs that pass within s and out again inside
// one step, which the engine counts and step ends cannot see (1 in 108 here; the double count
// was 24 in 108).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// Pairs within s, by index of the pair (i < j).
std::vector<bool> within(const Replicate& replicate, const ArenaGeometry& arena, double s) {
  const auto positions = replicate.engine().positions();
  std::vector<bool> close;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    for (std::size_t j = i + 1; j < positions.size(); ++j)
      close.push_back(arena.distance(positions[i], positions[j]) <= s);
  }
  return close;
}

TEST(EncounterCount, AMeetingPairClosingUpIsOneEncounter) {
  for (const std::string world : {"creation-50", "full-0.0025"}) {
    const WorldSpec spec =
        load_world(std::string(SWARMAGG_SOURCE_DIR) + "/worlds/paper/" + world + ".yaml",
                   {"run.duration=40", "engine.type=kinematic"});
    const ArenaGeometry arena = spec.arena.geometry();
    Replicate replicate(spec, 0);
    std::vector<bool> before = within(replicate, arena, spec.robots.detection_radius);
    std::uint64_t entries = 0;
    for (std::int64_t step = 0; step < spec.steps(); ++step) {
      replicate.step();
      const std::vector<bool> after = within(replicate, arena, spec.robots.detection_radius);
      for (std::size_t k = 0; k < after.size(); ++k) entries += after[k] && !before[k];
      before = after;
    }
    EXPECT_GT(entries, 5u) << world;
    EXPECT_GE(replicate.events().encounters, entries) << world;
    EXPECT_LE(replicate.events().encounters, entries + 1 + entries / 50) << world;
  }
}

}  // namespace
}  // namespace swarmagg
