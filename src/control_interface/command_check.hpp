#pragma once
// The velocities an engine accepts from a controller. A controller is the user's code, and one
// non-finite or absurd velocity spread silently: a NaN through Box2D's solver to every body of
// the world in one step (exit 0, NOA 0), an infinite one through the kinematic engine's
// neighbourhood to the agents around it. Engines check while they scan the commands anyway
// (command_within, branch-free) and name the first bad command (refuse_bad_command).
#include <span>
#include <stdexcept>
#include <string>

#include "control_interface/motion_command.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {

// A command no engine executes; Replicate names the controller that gave it.
class BadCommand : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The squared speed limit: ArenaGeometry::longest_move per step, for events up to `radius`
// (world files are held to the same for robots.speed).
double fastest_command_speed2(const ArenaGeometry& arena, double radius, double dt);

// Whether a squared speed is finite and within the limit (false for NaN).
inline bool command_within(double speed2, double fastest2) {
  return speed2 <= fastest2;
}

// Throws BadCommand naming the first agent whose command is not within the limit.
[[noreturn]] void refuse_bad_command(std::span<const MotionCommand> commands, double fastest2,
                                     double dt);

}  // namespace swarmagg
