#include "bench/lib/paper_density_world.hpp"

#include <cmath>
#include <string>

#include "config/world_loader.hpp"

namespace swarmagg {

WorldSpec paper_density_world(int n, const std::string& type) {
  WorldSpec spec;
  spec.name = "paper-density-" + std::to_string(n);
  spec.source = spec.name;
  const double side = 180.0 * std::sqrt(n / 150.0);
  spec.arena = {side, side, Topology::Torus};
  spec.robots.count = n;
  spec.controller.type = type;
  if (type == "collision") spec.controller.collision_mode = CollisionMode::Ghost;
  if (type == "bayindir") spec.controller.p_leave = 0.001;
  spec.run.replicates = 1;
  check_world(spec);
  return spec;
}

}  // namespace swarmagg
