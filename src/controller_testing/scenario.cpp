#include "controller_testing/scenario.hpp"

#include "config/world_loader.hpp"
#include "run/replicate.hpp"

namespace swarmagg::testing {

WorldSpec scenario_world(const std::string& yaml, const std::vector<std::string>& overrides) {
  return load_world_text(yaml, "scenario.yaml", overrides);
}

ScenarioEnd run_scenario(const WorldSpec& world, std::int64_t steps,
                         const std::function<void(const Replicate&)>& each_step, int replicate) {
  Replicate r(world, replicate);
  r.set_checking(true);
  for (std::int64_t k = 0; k < steps; ++k) {
    r.step();
    if (each_step) each_step(r);
  }
  ScenarioEnd end;
  end.steps = r.steps_done();
  end.states.assign(r.swarm().state.begin(), r.swarm().state.end());
  end.positions.assign(r.engine().positions().begin(), r.engine().positions().end());
  end.events = r.events();
  end.aggregate_sizes.assign(r.aggregates().sizes().begin(), r.aggregates().sizes().end());
  return end;
}

}  // namespace swarmagg::testing
