#include "control_interface/command_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace swarmagg {

double fastest_command_speed2(const ArenaGeometry& arena, double radius, double dt) {
  const double fastest = arena.longest_move(radius) / dt;
  return fastest * fastest;
}

void refuse_bad_command(std::span<const MotionCommand> commands, double fastest2, double dt) {
  for (std::size_t i = 0; i < commands.size(); ++i) {
    const Vec2 v = commands[i].velocity;
    if (command_within(norm2(v), fastest2)) continue;
    const bool finite = std::isfinite(v.x) && std::isfinite(v.y);
    char text[256];
    std::snprintf(text, sizeof text,
                  finite ? "commanded agent %zu a velocity of (%.6g, %.6g) u/tu, which moves it "
                           "farther in one step of %g tu than the engines resolve (a quarter of "
                           "the arena's shorter side, less half the sensing radius on a torus)"
                         : "commanded agent %zu a velocity of (%.6g, %.6g) u/tu, which is not "
                           "finite",
                  i, v.x, v.y, dt);
    throw BadCommand(text);
  }
  throw std::logic_error("refuse_bad_command: every command is within the limit");
}

}  // namespace swarmagg
