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
  std::span<const std::uint8_t> reflections() const override { return reflections_; }

 private:
  static double fastest_speed(std::span<const MotionCommand> commands) {
    double fastest2 = 0.0;
    for (const MotionCommand& c : commands) fastest2 = std::max(fastest2, norm2(c.velocity));
    return std::sqrt(fastest2);
  }

  void move(std::span<const MotionCommand> commands) {
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      positions_[i] += commands[i].velocity * stop_time_[i];
      reflections_[i] = arena_.torus() ? 0 : reflect_off_walls(positions_[i]);
      positions_[i] = arena_.wrap(positions_[i]);
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
    grid_.rebuild(arena_, reach, positions_);
    neighbours_.reset(positions_.size());
    pairs_.clear();
    const double sense2 = sensing_radius_ * sensing_radius_;
    const double pair2 = pair_reach * pair_reach;
    auto consider = [&](std::uint32_t i, std::uint32_t j) {
      if (j == i) return;
      const Vec2 d = arena_.displacement(positions_[i], positions_[j]);
      const double d2 = norm2(d);
      if (d2 <= sense2) neighbours_.push({j, d, std::sqrt(d2)});
      if (j > i && d2 <= pair2) pairs_.push_back({i, j, d});
    };
    const auto n = static_cast<std::uint32_t>(positions_.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      if (grid_.degenerate()) {
        for (std::uint32_t j = 0; j < n; ++j) consider(i, j);
      } else {
        grid_.for_each_nearby(i, [&](std::uint32_t j) { consider(i, j); });
      }
      neighbours_.close_agent(i);
    }
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
  GuardedMotion motion_;
};

}  // namespace

std::unique_ptr<Engine> make_kinematic_engine(const WorldSpec& spec,
                                              std::span<const Vec2> initial_positions) {
  return std::make_unique<KinematicEngine>(spec, initial_positions);
}

}  // namespace swarmagg
