#pragma once
// Hand-placed agents on a 100 x 100 torus with brute-force perception (within 6, s = 4), so
// observer tests need no engine: add agents, set their states, update().
#include <cmath>
#include <vector>

#include "geometry/arena_geometry.hpp"
#include "observers/aggregate_tracker.hpp"

namespace swarmagg::testing {

struct Scene {
  static constexpr double kDetectionRadius = 4.0;
  ArenaGeometry arena{100.0, 100.0, Topology::Torus};
  std::vector<Vec2> positions;
  SwarmState swarm;
  NeighbourLists neighbours;
  AggregateTracker tracker;

  std::uint32_t add(double x, double y, AgentState state = AgentState::Wait) {
    positions.push_back({x, y});
    return swarm.add(state);
  }
  // A hexagonal pack of `rings` rings around (x, y) at centre spacing `spacing`: 1, 7, 19,
  // 37 agents for 0..3 rings, the centre first, then ring by ring. Positions are wrapped
  // onto the torus. Returns the index of the centre.
  std::uint32_t add_hexagon(double x, double y, int rings, double spacing,
                            AgentState state = AgentState::Wait) {
    const auto first = static_cast<std::uint32_t>(positions.size());
    const double h = std::sqrt(3.0) / 2.0;
    for (int ring = 0; ring <= rings; ++ring) {
      for (int q = -ring; q <= ring; ++q) {
        for (int r = -ring; r <= ring; ++r) {
          if (std::max({std::abs(q), std::abs(r), std::abs(q + r)}) != ring) continue;
          const Vec2 p = arena.wrap({x + spacing * (q + 0.5 * r), y + spacing * h * r});
          add(p.x, p.y, state);
        }
      }
    }
    return first;
  }
  void update(AggregateLinks links = AggregateLinks::Proximity) {
    neighbours.reset(positions.size());
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
      for (std::uint32_t j = 0; j < positions.size(); ++j) {
        const Vec2 d = arena.displacement(positions[i], positions[j]);
        if (i != j && norm(d) <= 6.0) neighbours.push({j, d, norm(d)});
      }
      neighbours.close_agent(i);
    }
    tracker.update(neighbours, swarm, kDetectionRadius, links);
  }
};

}  // namespace swarmagg::testing
