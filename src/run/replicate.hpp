#pragma once
// One replicate: its own engine (bodies), controller state, aggregate tracker and event
// counts, all mutable and owned here, reading the shared immutable WorldSpec. A replicate
// is advanced one step at a time; observers read it through snapshot().
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "control_interface/controller_rules.hpp"
#include "control_interface/event_counts.hpp"
#include "control_interface/state_signals.hpp"
#include "controllers/controller_registry.hpp"
#include "core/agent_state.hpp"
#include "core/rng.hpp"
#include "engine/engine.hpp"
#include "observers/aggregate_tracker.hpp"
#include "observers/leave_episodes.hpp"
#include "observers/swarm_snapshot.hpp"

namespace swarmagg {

class Replicate {
 public:
  Replicate(const WorldSpec& spec, int index);
  // The replicate keeps a reference to its world: one made from a temporary spec would read
  // a destroyed spec after the statement (a silently wrong run, not an error).
  Replicate(WorldSpec&& spec, int index) = delete;
  Replicate(const WorldSpec&& spec, int index) = delete;
  ~Replicate();

  void step();  // advances by one step of dt
  // Checks the invariants (run/invariants.hpp) after every step; on by default in Debug.
  void set_checking(bool on) {
    checking_ = on;
    engine_->set_sleep_checks(on);
  }
  // Threads one step may use (results do not depend on it).
  void set_threads(int threads) { engine_->set_threads(threads); }
  std::int64_t steps_done() const { return step_; }
  double time() const { return static_cast<double>(step_) * spec_.engine.dt; }

  const WorldSpec& spec() const { return spec_; }
  // What the world's controller allows, computed once by the controller.
  const ControllerRules& rules() const { return rules_; }
  int index() const { return index_; }
  std::uint64_t seed() const { return rng_.key(); }
  const Engine& engine() const { return *engine_; }
  Engine& engine() { return *engine_; }
  const SwarmState& swarm() const { return swarm_; }
  const AggregateTracker& aggregates() const { return aggregates_; }
  const EventCounts& events() const { return events_; }
  // Cumulative growths by the size of the aggregate joined, [m] for m = 0..N.
  std::span<const std::uint64_t> growths_by_size() const { return growths_by_size_; }
  // The LEAVE episodes so far, judged between each decision and the move that follows it.
  const LeaveEpisodes& leave_episodes() const { return leave_episodes_; }
  SwarmSnapshot snapshot() const;
  // The last step's motion commands and the signals agents displayed during it.
  std::span<const MotionCommand> commands() const { return commands_; }
  std::span<const Signal> signals() const { return signals_; }

 private:
  void update_aggregates();
  void decide(const ControllerInput& input);
  std::string controller_context() const;

  const WorldSpec& spec_;
  int index_;
  CounterRng rng_;
  ControllerRules rules_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<Controller> controller_;
  SwarmState swarm_;
  AggregateTracker aggregates_;
  EventCounts events_;
  std::vector<std::uint64_t> growths_by_size_;
  LeaveEpisodes leave_episodes_;
  AgentArray<MotionCommand> commands_;
  AgentArray<Signal> signals_;
  std::int64_t step_ = 0;
#ifdef NDEBUG
  bool checking_ = false;
#else
  bool checking_ = true;
#endif
};

}  // namespace swarmagg
