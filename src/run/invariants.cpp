#include "run/invariants.hpp"

#include <cmath>
#include <string>

#include "config/world_keys.hpp"
#include "observers/timeseries_row.hpp"
#include "run/replicate.hpp"

namespace swarmagg {
namespace {

[[noreturn]] void violated(const Replicate& r, const std::string& what) {
  throw InvariantViolation("invariant violated in replicate " + std::to_string(r.index()) +
                           " at step " + std::to_string(r.steps_done()) + ": " + what);
}

std::string point(Vec2 p) { return "(" + format_number(p.x) + ", " + format_number(p.y) + ")"; }

void check_positions(const Replicate& r) {
  const auto positions = r.engine().positions();
  const ArenaSpec& arena = r.spec().arena;
  if (positions.size() != static_cast<std::size_t>(r.spec().robots.count)) {
    violated(r, "the engine has " + std::to_string(positions.size()) + " agents, the world " +
                    std::to_string(r.spec().robots.count));
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      violated(r, "agent " + std::to_string(i) + " has a non-finite position " + point(p));
    }
    if (p.x < 0.0 || p.x > arena.width || p.y < 0.0 || p.y > arena.height) {
      violated(r, "agent " + std::to_string(i) + " at " + point(p) + " is outside the arena");
    }
  }
}

void check_swarm(const Replicate& r) {
  const SwarmState& swarm = r.swarm();
  for (std::size_t i = 0; i < swarm.size(); ++i) {
    const Vec2 h = swarm.heading[i];
    if (!std::isfinite(h.x) || !std::isfinite(h.y) || std::fabs(norm(h) - 1.0) > 1e-6) {
      violated(r, "agent " + std::to_string(i) + " has heading " + point(h) + ", not a unit vector");
    }
  }
  int in_aggregates = 0;
  for (const std::int32_t size : r.aggregates().sizes()) in_aggregates += size;
  const auto counts = count_states(swarm.state);
  if (in_aggregates > counts.waiting) {
    violated(r, std::to_string(in_aggregates) + " agents in aggregates but only " +
                    std::to_string(counts.waiting) + " waiting");
  }
}

}  // namespace

void check_invariants(const Replicate& replicate) {
  check_positions(replicate);
  check_swarm(replicate);
}

}  // namespace swarmagg
