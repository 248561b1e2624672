#pragma once
// The one interface both engines implement. An engine owns the bodies of one replicate
// (positions and velocities), executes the controllers' motion commands for one step of dt,
// and reports what the agents perceive afterwards and which pairs met during the step.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/motion_command.hpp"
#include "control_interface/neighbour_lists.hpp"
#include "control_interface/wall_contacts.hpp"
#include "core/vec2.hpp"

namespace swarmagg {

struct StepReport {
  // Pairs whose centres came within the detection radius s during the step, having been
  // farther apart at its start (first contacts; swept, so none is missed at any speed).
  std::uint64_t encounters = 0;
};

class Engine {
 public:
  virtual ~Engine() = default;

  // Advances every body by one step of dt. `signals[i]` is what agent i displays during
  // the step; `commands[i]` what it asks for.
  virtual StepReport step(std::span<const MotionCommand> commands,
                          std::span<const Signal> signals) = 0;

  virtual std::span<const Vec2> positions() const = 0;
  // Agents within the sensing radius of each agent, as of the end of the last step (or
  // the initial placement before the first step).
  virtual const NeighbourLists& neighbours() const = 0;
  virtual std::span<const std::uint8_t> reflections() const = 0;  // Reflection bits

  // Threads the engine may use inside one step (results must not depend on it).
  virtual void set_threads(int /*threads*/) {}

  // Engines that let agents at rest sleep (skip the work of a step that would not move
  // them): how many slept in the last step, and, with checks on (each step then also
  // resolved in full), an agent that slept though the full step would have moved it or
  // changed what was counted (none: sleep changed nothing).
  virtual std::size_t asleep_count() const { return 0; }
  virtual void set_sleep_checks(bool /*on*/) {}
  virtual std::optional<std::uint32_t> sleeper_due_to_move() const { return std::nullopt; }
};

// Builds the engine `spec.engine.type` names, with the bodies at `initial_positions`.
std::unique_ptr<Engine> make_engine(const WorldSpec& spec, std::span<const Vec2> initial_positions);
// Throws the InputError make_engine would (a world the engine cannot run faithfully), without
// building it.
void check_engine_world(const WorldSpec& spec);

}  // namespace swarmagg
