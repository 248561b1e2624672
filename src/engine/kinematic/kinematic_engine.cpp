#include "engine/kinematic/kinematic_engine.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/neighbour_search.hpp"
#include "engine/kinematic/step_threads.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {
namespace {

// What the step needs to know about the commands before resolving them.
struct CommandSummary {
  double fastest = 0.0;  // largest commanded speed
  bool guarded = false;  // some agent may halt (halt_on or blocked_by bits)
};

CommandSummary summarise(std::span<const MotionCommand> commands) {
  double fastest2 = 0.0;
  SignalMask guards = 0;
  for (const MotionCommand& c : commands) {
    fastest2 = std::max(fastest2, norm2(c.velocity));
    guards |= c.halt_on | c.blocked_by;
  }
  return {std::sqrt(fastest2), guards != 0};
}

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
    rebuild_neighbourhood(nominal_speed_, true);
  }

  StepReport step(std::span<const MotionCommand> commands,
                  std::span<const Signal> signals) override {
    const CommandSummary summary = summarise(commands);
    // Faster than the candidates allow: search again (what agents perceive is unchanged).
    if (summary.fastest > pairs_speed_) rebuild_neighbourhood(summary.fastest, false);
    StepReport report;
    if (summary.guarded) {
      report.encounters = motion_.resolve(search_.candidates(), commands, signals, limits_);
      move_and_rebuild(commands, motion_.stop_times().data(), summary.fastest);
    } else {
      report.encounters = GuardedMotion::count_encounters(search_.candidates(), commands, limits_);
      move_and_rebuild(commands, nullptr, summary.fastest);
    }
    return report;
  }

  std::span<const Vec2> positions() const override { return positions_; }
  const NeighbourLists& neighbours() const override { return neighbours_; }
  // A torus reflects nothing; an empty span spares controllers a pass over N zeros.
  std::span<const std::uint8_t> reflections() const override {
    return arena_.torus() ? std::span<const std::uint8_t>{} : std::span<const std::uint8_t>(reflections_);
  }
  void set_threads(int threads) override { threads_.resize(std::max(1, threads)); }

 private:
  // Moves every agent for its stop time (dt for all when `stop_time` is null), then finds
  // the pairs for the next step and what each agent perceives.
  void move_and_rebuild(std::span<const MotionCommand> commands, const double* stop_time,
                        double fastest) {
    const SearchRadii radii = radii_for(std::max(nominal_speed_, fastest), true);
    const double dt = limits_.dt;
    if (stop_time == nullptr) {
      auto move = [&](std::uint32_t i, Vec2 p) { return move_agent(i, p, commands[i].velocity * dt); };
      search_.move_and_find(arena_, positions_, radii, threads_, move);
    } else {
      auto move = [&](std::uint32_t i, Vec2 p) {
        return move_agent(i, p, commands[i].velocity * stop_time[i]);
      };
      search_.move_and_find(arena_, positions_, radii, threads_, move);
    }
    neighbours_.assign_from_pairs(positions_.size(), search_.close_pairs());
  }

  // Agent i, at p, moves by `step`: wrapped on a torus, reflected off walls.
  Vec2 move_agent(std::uint32_t i, Vec2 p, Vec2 step) {
    p += step;
    if (arena_.torus()) {
      p = arena_.wrap(p);
    } else {
      reflections_[i] = reflect_off_walls(p);
    }
    positions_[i] = p;
    return p;
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

  // The radii of the search for pairs that can meet during the next step if no agent is
  // faster than `speed` (and with `perception`, of what each agent perceives).
  SearchRadii radii_for(double speed, bool perception) {
    pairs_speed_ = speed;
    SearchRadii radii;
    radii.sensing = sensing_radius_;
    radii.pair_reach =
        std::max(limits_.detection_radius, limits_.contact_distance) + 2.0 * speed * limits_.dt;
    radii.perception = perception;
    return radii;
  }

  void rebuild_neighbourhood(double speed, bool perception) {
    search_.find(arena_, positions_, radii_for(speed, perception), threads_);
    if (perception) neighbours_.assign_from_pairs(positions_.size(), search_.close_pairs());
  }

  ArenaGeometry arena_;
  MotionLimits limits_;
  double body_radius_;
  double sensing_radius_;
  double nominal_speed_;
  double pairs_speed_ = 0.0;
  std::vector<Vec2> positions_;
  std::vector<std::uint8_t> reflections_;
  StepThreads threads_;
  NeighbourSearch search_;
  NeighbourLists neighbours_;
  GuardedMotion motion_;
};

}  // namespace

std::unique_ptr<Engine> make_kinematic_engine(const WorldSpec& spec,
                                              std::span<const Vec2> initial_positions) {
  return std::make_unique<KinematicEngine>(spec, initial_positions);
}

}  // namespace swarmagg
