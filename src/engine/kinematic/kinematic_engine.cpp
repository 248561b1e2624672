#include "engine/kinematic/kinematic_engine.hpp"

#include <algorithm>
#include <vector>

#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/uniform_grid.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {
namespace {

class KinematicEngine final : public Engine {
 public:
  KinematicEngine(const WorldSpec& spec, std::span<const Vec2> initial_positions)
      : arena_(spec.arena),
        // Halting a hair inside s guarantees the halted pair perceives each other afterwards.
        limits_{spec.robots.detection_radius * (1.0 - 1e-9), 2.0 * spec.robots.radius,
                spec.engine.dt},
        body_radius_(spec.robots.radius),
        sensing_radius_(spec.sensing_radius()),
        nominal_speed_(spec.robots.speed),
        positions_(initial_positions.begin(), initial_positions.end()),
        reflections_(positions_.size(), 0) {
    rebuild_neighbourhood(nominal_speed_);
  }

  StepReport step(std::span<const MotionCommand> commands,
                  std::span<const Signal> signals) override {
    const double fastest = fastest_speed(commands);
    if (fastest > pairs_speed_) rebuild_neighbourhood(fastest);
    StepReport report;
    report.encounters = motion_.resolve(pairs_, commands, signals, limits_, stop_time_);
    move(commands);
    rebuild_neighbourhood(std::max(nominal_speed_, fastest));
    return report;
  }

  std::span<const Vec2> positions() const override { return positions_; }
  const NeighbourLists& neighbours() const override { return neighbours_; }
  // A torus reflects nothing; an empty span spares controllers a pass over N zeros.
  std::span<const std::uint8_t> reflections() const override {
    return arena_.torus() ? std::span<const std::uint8_t>{} : std::span<const std::uint8_t>(reflections_);
  }

 private:
  static double fastest_speed(std::span<const MotionCommand> commands) {
    double fastest2 = 0.0;
    for (const MotionCommand& c : commands) fastest2 = std::max(fastest2, norm2(c.velocity));
    return std::sqrt(fastest2);
  }

  void move(std::span<const MotionCommand> commands) {
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      positions_[i] += commands[i].velocity * stop_time_[i];
      if (arena_.torus()) {
        positions_[i] = arena_.wrap(positions_[i]);
      } else {
        reflections_[i] = reflect_off_walls(positions_[i]);
      }
    }
  }

  std::uint8_t reflect_off_walls(Vec2& p) const {
    std::uint8_t bits = 0;
    auto reflect = [&](double& x, double length, std::uint8_t bit) {
      const double low = body_radius_;
      const double high = length - body_radius_;
      if (x < low) {
        x = std::min(2.0 * low - x, high);
        bits |= bit;
      } else if (x > high) {
        x = std::max(2.0 * high - x, low);
        bits |= bit;
      }
    };
    reflect(p.x, arena_.width(), ReflectedX);
    reflect(p.y, arena_.height(), ReflectedY);
    return bits;
  }

  // Rebuilds the grid on the current positions, each agent's perceived neighbours, and the
  // pairs that can meet during the next step if no agent is faster than `speed`.
  void rebuild_neighbourhood(double speed) {
    pairs_speed_ = speed;
    const double pair_reach =
        std::max(limits_.detection_radius, limits_.contact_distance) + 2.0 * speed * limits_.dt;
    const double reach = std::max(sensing_radius_, pair_reach);
    // Cells much smaller than the spacing between agents cost more to sweep than the
    // distance checks they save; about 1.4 agents per cell measured best (callgrind).
    const double spacing = std::sqrt(arena_.width() * arena_.height() /
                                     std::max<std::size_t>(1, positions_.size()));
    grid_.rebuild(arena_, std::max(reach, 1.2 * spacing), positions_);
    close_.clear();
    pairs_.clear();
    const double sense2 = sensing_radius_ * sensing_radius_;
    const double pair2 = pair_reach * pair_reach;
    grid_.for_each_close_pair(reach, [&](std::uint32_t i, std::uint32_t j, Vec2 d, double d2) {
      if (d2 <= sense2) close_.push_back({i, j, d, std::sqrt(d2)});
      if (d2 <= pair2) pairs_.push_back({i, j, d});
    });
    neighbours_.assign_from_pairs(positions_.size(), close_);
  }

  ArenaGeometry arena_;
  MotionLimits limits_;
  double body_radius_;
  double sensing_radius_;
  double nominal_speed_;
  double pairs_speed_ = 0.0;
  std::vector<Vec2> positions_;
  std::vector<std::uint8_t> reflections_;
  std::vector<double> stop_time_;
  UniformGrid grid_;
  NeighbourLists neighbours_;
  std::vector<CandidatePair> pairs_;
  std::vector<ClosePair> close_;
  GuardedMotion motion_;
};

}  // namespace

std::unique_ptr<Engine> make_kinematic_engine(const WorldSpec& spec,
                                              std::span<const Vec2> initial_positions) {
  return std::make_unique<KinematicEngine>(spec, initial_positions);
}

}  // namespace swarmagg
