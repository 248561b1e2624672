#include "engine/kinematic/kinematic_engine.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <vector>

#include "control_interface/command_check.hpp"
#include "core/agent_array.hpp"
#include "engine/kinematic/guarded_motion.hpp"
#include "engine/kinematic/sleeping_islands.hpp"
#include "engine/kinematic/step_threads.hpp"
#include "engine/kinematic/verlet_pairs.hpp"
#include "geometry/arena_geometry.hpp"

namespace swarmagg {
namespace {

// What the step needs to know about the commands before resolving them.
struct CommandSummary {
  double fastest = 0.0;    // largest commanded speed
  bool guarded = false;    // some agent may halt (halt_on or blocked_by bits)
  std::size_t moving = 0;  // agents commanded to move
  bool within = true;      // every speed finite and within the limit (command_check.hpp)
};

bool zero_velocity(Vec2 v) {
  return (v.x == 0.0) & (v.y == 0.0);
}

// Perceiving halts stop a hair inside the detection radius, this fraction of it: the halted
// pair then perceives each other.
constexpr double kHaltInside = 1e-9;
// Slides slower than this fraction of the nominal speed halt (MotionLimits::min_slide_speed):
// as Box2D lets bodies slower than its linear sleep tolerance (0.01) come to rest.
constexpr double kMinSlideFraction = 0.01;
// Below the world's shortest move (ArenaGeometry::position_resolution), and below a quarter
// of the hair a perceiving halt stops inside s: two searchers meant to halt on each other whose
// last moves were both dropped are still within s (in an arena of 5,000 u, 10^-12 of its side
// exceeds that hair, and such a pair froze just outside s for ever).
double unresolved_move2(const ArenaGeometry& arena, double detection_radius) {
  const double longest =
      std::min(arena.position_resolution(), 0.25 * kHaltInside * detection_radius);
  return longest * longest;
}

// Agents per move task below which waking another thread costs more than it saves.
constexpr std::size_t kAgentsPerMoveTask = 65536;
// The Verlet list's skin, in steps of two agents at the nominal speed closing in on each
// other: the list is searched anew about once every this many steps.
constexpr double kSkinSteps = 8.0;
// Passes over the bent agents (scattered ids) request their data this many agents ahead.
constexpr std::size_t kBentAhead = 16;

// Two running maxima (even and odd agents) keep two comparisons in flight; the maximum of
// exact values does not depend on the order it is taken in.
// A NaN passes the maxima by (every comparison with it is false) but not the sum, which it
// turns to NaN: the sum costs an addition a command where a test of each costs a branch-free
// comparison and a mask (3 % of the ghost bench).
CommandSummary summarise(std::span<const MotionCommand> commands, double fastest2) {
  double even2 = 0.0, odd2 = 0.0, sum2 = 0.0;
  SignalMask guards = 0;
  std::size_t moving = 0;
  const MotionCommand* c = commands.data();
  const std::size_t n = commands.size();
  std::size_t i = 0;
  for (; i + 1 < n; i += 2) {
    const double a = norm2(c[i].velocity), b = norm2(c[i + 1].velocity);
    even2 = a > even2 ? a : even2;
    odd2 = b > odd2 ? b : odd2;
    sum2 += a + b;
    moving += static_cast<std::size_t>(a > 0.0) + static_cast<std::size_t>(b > 0.0);
    guards |= c[i].halt_on | c[i].blocked_by | c[i + 1].halt_on | c[i + 1].blocked_by;
  }
  if (i < n) {
    even2 = std::max(even2, norm2(c[i].velocity));
    sum2 += norm2(c[i].velocity);
    moving += static_cast<std::size_t>(norm2(c[i].velocity) > 0.0);
    guards |= c[i].halt_on | c[i].blocked_by;
  }
  const double largest2 = std::max(even2, odd2);
  const bool within = command_within(largest2, fastest2) && !std::isnan(sum2);
  return {std::sqrt(largest2), guards != 0, moving, within};
}

class KinematicEngine final : public Engine {
 public:
  KinematicEngine(const WorldSpec& spec, std::span<const Vec2> initial_positions)
      : arena_(spec.arena.geometry()),
        limits_{
            spec.robots.detection_radius * (1.0 - kHaltInside),
            2.0 * spec.robots.radius,
            spec.engine.dt,
            spec.engine.contact,
            !arena_.torus(),
            WallBounds{{spec.robots.radius, spec.robots.radius},
                       {arena_.width() - spec.robots.radius, arena_.height() - spec.robots.radius}},
            kMinSlideFraction * spec.robots.speed,
            unresolved_move2(arena_, spec.robots.detection_radius)},
        body_radius_(spec.robots.radius),
        sensing_radius_(spec.perception_radius()),
        nominal_speed_(spec.robots.speed),
        fastest_command2_(fastest_command_speed2(arena_, spec.sensing_radius(), spec.engine.dt)),
        positions_(initial_positions.begin(), initial_positions.end()),
        reflections_(positions_.size(), 0),
        pairs_(kSkinSteps * 2.0 * spec.robots.speed * spec.engine.dt) {
    // Without perception every agent's list stays empty.
    neighbours_.reset(positions_.size());
    rebuild_neighbourhood(nominal_speed_, true, 0.0);
  }

  StepReport step(std::span<const MotionCommand> commands,
                  std::span<const Signal> signals) override {
    // A world that slept whole in the last step, on pairs it kept, sleeps whole again when
    // every command and signal repeats: nobody moved, so deciding again would find every
    // agent at rest on the same pairs and reach (the same summary of the same commands).
    if (slept_whole_ && !sleep_checks_ && islands_.inputs_repeat(commands, signals)) return {};
    slept_whole_ = false;
    const CommandSummary summary = summarise(commands, fastest_command2_);
    if (!summary.within) refuse_bad_command(commands, fastest_command2_, limits_.dt);
    // Faster than the candidates allow: search again (what agents perceive is unchanged).
    if (summary.fastest > pairs_speed_) {
      rebuild_neighbourhood(summary.fastest, false, 0.0);
      pairs_kept_ = false;
    }
    StepReport report;
    if (summary.guarded) {
      islands_.decide(positions_, commands, signals, pairs_.candidates(), pairs_speed_,
                      met_last_step(), pairs_kept_ || pairs_.kept(), last_rest_);
      // Everybody asleep: nothing moves, nothing meets, the pairs and lists stay (unless the
      // radii changed). With checks on, the step is resolved as usual, to be checked.
      resolved_last_ = islands_.sleepers().size() < positions_.size() || sleep_checks_;
      if (!resolved_last_) {
        const double speed = std::max(nominal_speed_, summary.fastest);
        pairs_kept_ = speed == pairs_speed_;
        if (!pairs_kept_) rebuild_neighbourhood(speed, true, 0.0);
        slept_whole_ = pairs_kept_;
        last_rest_ = {true, pressing_sleepers(commands)};
        return report;
      }
      const std::span<const MotionCommand> resolved = without_sleepers(commands);
      report.encounters =
          motion_.resolve(pairs_.candidates(), resolved, signals, limits_, positions_);
      if (sleep_checks_) check_sleepers(commands, signals, report.encounters);
      move_and_rebuild(resolved, &motion_, summary.fastest);
      last_rest_.pressing = pressing_sleepers(commands) + bent_that_stayed(commands);
      last_rest_.still = last_rest_.pressing == summary.moving;
    } else {
      resolved_last_ = false;
      islands_.forget();
      last_rest_ = {summary.moving == 0, 0};
      report.encounters = GuardedMotion::count_encounters(pairs_.candidates(), commands, limits_);
      move_and_rebuild(commands, nullptr, summary.fastest);
    }
    return report;
  }

  std::size_t asleep_count() const override { return islands_.sleepers().size(); }
  void set_sleep_checks(bool on) override { sleep_checks_ = on; }
  std::optional<std::uint32_t> sleeper_due_to_move() const override { return sleep_violation_; }

  std::span<const Vec2> positions() const override { return positions_; }
  const NeighbourLists& neighbours() const override { return neighbours_; }
  // A torus reflects nothing; an empty span spares controllers a pass over N zeros.
  std::span<const std::uint8_t> reflections() const override {
    return arena_.torus() ? std::span<const std::uint8_t>{}
                          : std::span<const std::uint8_t>(reflections_);
  }
  void set_threads(int threads) override { threads_.resize(std::max(1, threads)); }

 private:
  // Moves every agent as `motion` resolved it (with its commanded velocity for all of dt
  // when `motion` is null), then finds the pairs for the next step and what each agent
  // perceives.
  void move_and_rebuild(std::span<const MotionCommand> commands, const GuardedMotion* motion,
                        double fastest) {
    const std::size_t n = positions_.size();
    const int tasks = static_cast<int>(std::clamp<std::size_t>(
        n / kAgentsPerMoveTask, 1, static_cast<std::size_t>(threads_.size())));
    // On a torus every agent first moves as commanded, in one plain loop, and the few whose
    // motion changed are then moved again from where they started.
    const bool patch_bent = motion != nullptr && arena_.torus();
    if (motion != nullptr) remember_starts(motion->bent_agents());
    auto move = [&](int task) {
      const std::size_t first = StepThreads::slice_begin(n, task, tasks);
      const std::size_t last = StepThreads::slice_begin(n, task + 1, tasks);
      if (motion == nullptr || patch_bent) {
        const double dt = limits_.dt;
        move_range(
            first, last, [commands, dt](std::size_t i) { return commands[i].velocity * dt; },
            [](std::size_t) { return std::uint8_t{0}; });
      } else {
        move_range(
            first, last,
            [motion](std::size_t i) { return motion->displacement(static_cast<std::uint32_t>(i)); },
            [motion](std::size_t i) {
              return motion->wall_contacts(static_cast<std::uint32_t>(i));
            });
      }
    };
    if (!arena_.torus()) remember_sleepers_reflections();
    threads_.run(tasks, move);
    if (patch_bent) move_bent_from_starts(*motion);
    keep_sleepers_in_place();
    const double speed = std::max(nominal_speed_, fastest);
    // When no agent moved and the radii stay, the pairs and what each agent perceives are
    // those found last: a world at rest costs no search and no lists. When only agents far
    // from everybody moved (searchers away from the packed aggregates), every pair measures
    // as before: the pairs and lists are kept too.
    const SleepingIslands::Moved moved = islands_.who_moved(
        positions_, [this](std::uint32_t agent) { return pairs_.paired(agent); });
    pairs_kept_ =
        motion != nullptr && speed == pairs_speed_ && moved == SleepingIslands::Moved::Nobody;
    if (pairs_kept_) return;
    // No agent moved farther than the fastest command for dt: the guarded motion only
    // shortens or projects commanded moves, and a wall's mirror image lies nearer.
    // (A step resolved without guards forgot the islands: who moved is then unknown.)
    rebuild_neighbourhood(speed, true, fastest * limits_.dt,
                          moved == SleepingIslands::Moved::Paired);
  }

  // Of the agents commanded to move, those that stayed where they were: the sleepers, and
  // those whose motion changed (starts_) that ended the step where they started, bit for bit
  // (halted at once, or within a rounding error of it). All others moved their whole step.
  std::size_t pressing_sleepers(std::span<const MotionCommand> commands) const {
    std::size_t pressing = 0;
    for (const std::uint32_t agent : islands_.sleepers()) {
      pressing += static_cast<std::size_t>(!zero_velocity(commands[agent].velocity));
    }
    return pressing;
  }
  std::size_t bent_that_stayed(std::span<const MotionCommand> commands) const {
    std::size_t stayed = 0;
    for (std::size_t k = 0; k < starts_.size(); ++k) {
      if (k + kBentAhead < starts_.size()) {
        const std::uint32_t ahead = starts_[k + kBentAhead].first;
        __builtin_prefetch(&positions_[ahead]);
        __builtin_prefetch(&commands[ahead]);
      }
      const auto& [agent, start] = starts_[k];
      stayed += static_cast<std::size_t>(same_bits(start, positions_[agent]) &
                                         !zero_velocity(commands[agent].velocity));
    }
    return stayed;
  }

  // The agents the last step's guarded motion saw meet (none when it was not resolved).
  std::span<const std::uint32_t> met_last_step() const {
    return resolved_last_ ? motion_.met_agents() : std::span<const std::uint32_t>{};
  }

  // The commands the guarded motion resolves: sleepers stand (what they would do anyway), so
  // that nothing of theirs is scheduled.
  std::span<const MotionCommand> without_sleepers(std::span<const MotionCommand> commands) {
    if (islands_.sleepers().empty()) return commands;
    resolved_commands_.assign(commands.begin(), commands.end());
    for (const std::uint32_t agent : islands_.sleepers()) resolved_commands_[agent].velocity = {};
    return resolved_commands_;
  }

  // Sleepers keep every bit of their positions and, between walls, the walls they touched.
  void remember_sleepers_reflections() {
    sleepers_reflections_.clear();
    for (const std::uint32_t agent : islands_.sleepers()) {
      sleepers_reflections_.push_back(reflections_[agent]);
    }
  }
  void keep_sleepers_in_place() {
    const std::span<const std::uint32_t> sleepers = islands_.sleepers();
    for (std::size_t k = 0; k < sleepers.size(); ++k) {
      positions_[sleepers[k]] = islands_.start_of(sleepers[k]);
      if (!arena_.torus()) reflections_[sleepers[k]] = sleepers_reflections_[k];
    }
  }

  // Resolves the step again in full, with every command as given, and records an agent that
  // slept though it would have moved, or any difference in where the others go or in the
  // encounters counted.
  void check_sleepers(std::span<const MotionCommand> commands, std::span<const Signal> signals,
                      std::uint64_t encounters) {
    if (sleep_violation_ || islands_.sleepers().empty()) return;
    const std::uint64_t full =
        full_motion_.resolve(pairs_.candidates(), commands, signals, limits_, positions_);
    for (std::uint32_t agent = 0; agent < positions_.size(); ++agent) {
      const Vec2 start = positions_[agent];
      const Vec2 due = moved_from(start, full_motion_.displacement(agent));
      const Vec2 given =
          islands_.asleep(agent) ? start : moved_from(start, motion_.displacement(agent));
      if (!same_bits(due, given) || full != encounters) {
        sleep_violation_ = agent;
        return;
      }
    }
  }

  // Where a move by `displacement` from `start` ends (the arena's edges applied).
  Vec2 moved_from(Vec2 start, Vec2 displacement) const {
    Vec2 p = start + displacement;
    if (arena_.torus()) return on_torus(p);
    reflect_off_walls(p);
    return p;
  }

  void remember_starts(std::span<const std::uint32_t> agents) {
    starts_.clear();
    for (std::size_t k = 0; k < agents.size(); ++k) {
      if (k + kBentAhead < agents.size()) __builtin_prefetch(&positions_[agents[k + kBentAhead]]);
      starts_.push_back({agents[k], positions_[agents[k]]});
    }
  }

  void move_bent_from_starts(const GuardedMotion& motion) {
    for (std::size_t k = 0; k < starts_.size(); ++k) {
      if (k + kBentAhead < starts_.size())
        motion.prefetch_displacement(starts_[k + kBentAhead].first);
      const auto& [agent, start] = starts_[k];
      positions_[agent] = on_torus(start + motion.displacement(agent));
    }
  }

  // Only the few agents that crossed an edge are wrapped.
  Vec2 on_torus(Vec2 p) const {
    const bool inside =
        (p.x >= 0.0) & (p.x < arena_.width()) & (p.y >= 0.0) & (p.y < arena_.height());
    return inside ? p : arena_.wrap(p);
  }

  // Plain loops over raw arrays (nothing the stores could alias), wrapping only the few
  // agents that crossed an edge. Between walls, bodies the guarded motion stopped or slid at
  // a wall report it as a reflection; point particles that crossed a wall are mirrored.
  template <typename Displacement, typename WallContacts>
  void move_range(std::size_t first, std::size_t last, Displacement displacement,
                  WallContacts wall_contacts) {
    Vec2* position = positions_.data();
    if (arena_.torus()) {
      for (std::size_t i = first; i < last; ++i)
        position[i] = on_torus(position[i] + displacement(i));
      return;
    }
    for (std::size_t i = first; i < last; ++i) {
      position[i] += displacement(i);
      const std::uint8_t walls = wall_contacts(i);
      reflections_[i] = static_cast<std::uint8_t>(reflect_off_walls(position[i]) |
                                                  ((walls & WallX) ? ReflectedX : 0) |
                                                  ((walls & WallY) ? ReflectedY : 0));
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

  // `moved`: how far any agent moved at most since the last rebuild; `pairs_moved`: whether
  // an agent of a listed pair may have moved since (VerletPairs::find).
  void rebuild_neighbourhood(double speed, bool perception, double moved, bool pairs_moved = true) {
    perception = perception && sensing_radius_ > 0.0;
    pairs_.find(arena_, positions_, radii_for(speed, perception), moved, threads_, neighbours_,
                pairs_moved);
  }

  ArenaGeometry arena_;
  MotionLimits limits_;
  double body_radius_;
  double sensing_radius_;
  double nominal_speed_;
  double fastest_command2_;  // the squared speed limit of commands (command_check.hpp)
  double pairs_speed_ = 0.0;
  AgentArray<Vec2> positions_;
  std::vector<std::uint8_t> reflections_;
  StepThreads threads_;
  VerletPairs pairs_;
  NeighbourLists neighbours_;
  GuardedMotion motion_;
  SleepingIslands islands_;
  AgentArray<MotionCommand> resolved_commands_;
  std::vector<std::uint8_t> sleepers_reflections_;
  bool sleep_checks_ = false;
  bool resolved_last_ = false;  // the last step ran the guarded motion
  bool pairs_kept_ = false;     // the last step found no new pairs: nothing moved
  bool slept_whole_ = false;    // and every agent slept in it
  LastStepRest last_rest_;      // what the last step's motion left at rest
  GuardedMotion full_motion_;   // the check's resolution in full
  std::optional<std::uint32_t> sleep_violation_;
  // Where the agents whose motion changed started the last step resolved.
  std::vector<std::pair<std::uint32_t, Vec2>> starts_;
};

}  // namespace

std::unique_ptr<Engine> make_kinematic_engine(const WorldSpec& spec,
                                              std::span<const Vec2> initial_positions) {
  return std::make_unique<KinematicEngine>(spec, initial_positions);
}

}  // namespace swarmagg
