#include "engine/box2d/box2d_engine.hpp"
#include "engine/engine.hpp"
#include "engine/kinematic/kinematic_engine.hpp"

namespace swarmagg {

std::unique_ptr<Engine> make_engine(const WorldSpec& spec,
                                    std::span<const Vec2> initial_positions) {
  switch (spec.engine.type) {
    case EngineType::Kinematic:
      return make_kinematic_engine(spec, initial_positions);
    case EngineType::Box2D:
      return make_box2d_engine(spec, initial_positions);
  }
  return nullptr;
}

void check_engine_world(const WorldSpec& spec) {
  if (spec.engine.type == EngineType::Box2D) check_box2d_world(spec);
}

}  // namespace swarmagg
