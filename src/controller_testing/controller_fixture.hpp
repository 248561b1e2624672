#pragma once
// Builds the perception a controller sees from hand-placed agents (brute force, torus) and
// runs one decision, so controller tests need no engine.
#include <vector>

#include "controllers/controller_registry.hpp"
#include "geometry/arena_geometry.hpp"
#include "observers/aggregate_tracker.hpp"

namespace swarmagg::testing {

struct ControllerFixture {
  WorldSpec spec;
  std::vector<Vec2> positions;
  SwarmState swarm;
  NeighbourLists neighbours;
  AggregateTracker aggregates;
  EventCounts events;
  std::vector<std::uint64_t> growths_by_size;  // [m]: growths of aggregates of m, cumulative
  std::vector<MotionCommand> commands;
  std::vector<std::uint8_t> reflections;
  std::unique_ptr<Controller> controller;
  std::int64_t step = 0;

  explicit ControllerFixture(WorldSpec world) : spec(std::move(world)) {
    spec.arena = {100.0, 100.0, Topology::Torus};
  }

  // Adds an agent at (x, y) in `state`, heading +x; returns its index.
  std::uint32_t add(double x, double y, AgentState state = AgentState::Go) {
    positions.push_back({x, y});
    return swarm.add(state);
  }

  void perceive() {
    const ArenaGeometry arena = spec.arena.geometry();
    neighbours.reset(positions.size());
    for (std::uint32_t i = 0; i < positions.size(); ++i) {
      for (std::uint32_t j = 0; j < positions.size(); ++j) {
        const Vec2 d = arena.displacement(positions[i], positions[j]);
        if (j != i && norm(d) <= spec.sensing_radius()) neighbours.push({j, d, norm(d)});
      }
      neighbours.close_agent(i);
    }
    aggregates.update(neighbours, swarm, spec.robots.detection_radius,
                      controller_rules(spec).partners_only ? AggregateLinks::PartnersOnly
                                                           : AggregateLinks::Proximity);
  }

  void decide() {
    if (!controller) controller = make_controller(spec);
    perceive();
    // Kept from the decision before, as a run keeps them: a command the controller does not
    // write is last step's there too (it was reset here, so such a bug passed its tests).
    if (commands.size() != positions.size()) commands.assign(positions.size(), MotionCommand{});
    reflections.assign(positions.size(), 0);
    growths_by_size.resize(positions.size() + 1, 0);
    const ControllerInput input{step++, neighbours, reflections, aggregates.facts(),
                                growths_by_size};
    controller->decide(input, swarm, CounterRng(11), commands, events);
  }
};

}  // namespace swarmagg::testing
