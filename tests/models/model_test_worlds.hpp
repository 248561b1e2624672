#pragma once
// Worlds for the model tests, set like the paper's experiments (docs/reproducing.md): s = 4, r = 1,
// v = 1, dt = 0.1. The models start from the second-order formula: the default start, a
// sample of placements, needs the simulation (tests/run/placement_sample_test.cpp).
#include "config/world_spec.hpp"

namespace swarmagg::testing {

inline WorldSpec bayindir_world(int agents, double p_leave, bool join, bool leave,
                                double side = 180.0) {
  WorldSpec world;
  world.arena.width = world.arena.height = side;
  world.robots.count = agents;
  world.controller.type = "bayindir";
  world.controller.p_leave = p_leave;
  world.controller.join = join;
  world.controller.leave = leave;
  world.model.initial_state = InitialState::PlacementSecondOrder;
  return world;
}

inline WorldSpec soysal_world(int agents, double side, double p0 = 2e-5,
                              LeaveLaw law = LeaveLaw::Constant) {
  WorldSpec world;
  world.arena.width = world.arena.height = side;
  world.robots.count = agents;
  world.controller.type = "soysal";
  world.controller.p0 = p0;
  world.controller.leave_law = law;
  world.model.initial_state = InitialState::PlacementSecondOrder;
  return world;
}

}  // namespace swarmagg::testing
