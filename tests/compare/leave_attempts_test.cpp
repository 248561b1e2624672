#include "compare/leave_attempts.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "config/world_loader.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

// A hexagonal aggregate of seven at spacing 3 (between 2r = 2 and s = 4): the centre
// (agent 0) has 6 members within s, each rim agent 3 (the centre and its two ring
// neighbours; the next ring agents are 3 sqrt(3) > s away). Compaction is off so that it
// keeps that spacing.
WorldSpec hexagon_world(std::uint64_t seed) {
  return load_world_text(R"(
name: hexagon
arena: {width: 40, height: 40}
robots:
  count: 7
  placement: [[20, 20, 0], [23, 20, 0], [21.5, 22.598076, 0], [18.5, 22.598076, 0],
              [17, 20, 0], [18.5, 17.401924, 0], [21.5, 17.401924, 0]]
controller: {type: bayindir, join: true, leave: true, p_leave: 0.001, leave_timeout: 10,
             compaction: {enabled: false}}
run: {duration: 200, replicates: 1, seed: )" +
                             std::to_string(seed) + "}\n",
                         "hexagon");
}

std::vector<LeaveAttempt> watch(const WorldSpec& spec) {
  Replicate replicate(spec, 0);
  std::vector<LeaveAttempt> attempts;
  LeaveAttemptObserver observer(kDefaultRimBelow, &attempts);
  observer.observe(replicate);
  for (std::int64_t s = 0; s < spec.steps(); ++s) {
    replicate.step();
    observer.observe(replicate);
  }
  observer.finish();
  std::sort(attempts.begin(), attempts.end(),
            [](const LeaveAttempt& a, const LeaveAttempt& b) { return a.step < b.step; });
  return attempts;
}

// The first attempt, while the hexagon is still whole, and nobody else leaving until it ends.
bool first_is_clean(const std::vector<LeaveAttempt>& attempts, std::int64_t timeout_steps) {
  if (attempts.empty()) return false;
  return attempts.size() == 1 || attempts[1].step > attempts[0].step + timeout_steps;
}

TEST(LeaveAttempts, HexagonCentreIsInsideAndRingIsRim) {
  int centre_seen = 0;
  int rim_seen = 0;
  for (std::uint64_t seed = 1; seed <= 80; ++seed) {
    const std::vector<LeaveAttempt> attempts = watch(hexagon_world(seed));
    if (!first_is_clean(attempts, 100)) continue;
    const LeaveAttempt& first = attempts.front();
    if (first.agent == 0) {
      ++centre_seen;
      EXPECT_EQ(first.members_near, 6) << "seed " << seed;
      EXPECT_FALSE(first.rim);
      EXPECT_FALSE(first.got_out) << "the ring holds the centre in (seed " << seed << ")";
    } else {
      ++rim_seen;
      EXPECT_EQ(first.members_near, 3) << "seed " << seed;
      EXPECT_TRUE(first.rim);
      EXPECT_TRUE(first.got_out) << "a ring agent walks straight out (seed " << seed << ")";
    }
  }
  EXPECT_GT(centre_seen, 0);
  EXPECT_GT(rim_seen, 0);
}

TEST(LeaveAttempts, MembersWithinCountsTheHexagonByHand) {
  const WorldSpec spec = hexagon_world(1);
  Replicate replicate(spec, 0);
  replicate.step();  // everyone perceives someone and waits
  const auto aggregate_of = replicate.aggregates().aggregate_of();
  EXPECT_EQ(members_within(0, replicate.engine().neighbours(), aggregate_of, 4.0), 6);
  for (AgentId ring = 1; ring < 7; ++ring) {
    EXPECT_EQ(members_within(ring, replicate.engine().neighbours(), aggregate_of, 4.0), 3);
  }
}

}  // namespace
}  // namespace swarmagg
