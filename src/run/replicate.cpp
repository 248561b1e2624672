#include "run/replicate.hpp"

#include <cmath>
#include <new>
#include <stdexcept>
#include <system_error>

#include "control_interface/command_check.hpp"
#include "core/errors.hpp"
#include "run/initial_placement.hpp"
#include "run/interrupt.hpp"
#include "run/invariants.hpp"

namespace swarmagg {

namespace {

// A leaver is held by its aggregate as far as its controller would steer back to it: the
// approach radius of a controller that approaches, else the detection radius.
EpisodeRules episode_rules(const WorldSpec& spec, const ControllerRules& rules) {
  return {.escape_radius = rules.allows(AgentState::Approach) ? spec.controller.approach_radius
                                                              : spec.robots.detection_radius,
          .detection_radius = spec.robots.detection_radius,
          .return_window_steps = std::llround(spec.return_window() / spec.engine.dt)};
}

}  // namespace

Replicate::Replicate(const WorldSpec& spec, int index)
    : spec_(spec),
      index_(index),
      rng_(CounterRng::for_replicate(spec.run.seed, static_cast<std::uint64_t>(index))),
      rules_(controller_rules(spec)),
      leave_episodes_(spec.robots.count, episode_rules(spec, rules_), ShapeRules::for_world(spec)) {
  InitialPlacement placement = place_agents(spec, rng_);
  engine_ = make_engine(spec, placement.positions);
  engine_->set_sleep_checks(checking_);
  controller_ = make_controller(spec);
  swarm_.resize(placement.positions.size());
  swarm_.heading.assign(placement.headings.begin(), placement.headings.end());
  commands_.resize(swarm_.size());
  signals_.resize(swarm_.size());
  growths_by_size_.assign(swarm_.size() + 1, 0);
  update_aggregates();
}

Replicate::~Replicate() = default;

// "controller 'timer' (replicate 0, deciding at step 5) ": where a controller's error came
// from. Steps are numbered as timeseries.csv numbers its rows (step 5: the state at 5 dt),
// and as the invariants' messages name the state they found broken.
std::string Replicate::controller_context() const {
  return "controller '" + spec_.controller.type + "' (replicate " + std::to_string(index_) +
         ", deciding at step " + std::to_string(step_) + ") ";
}

// A controller is the user's code: what it throws, and a swarm it resized, are reported naming
// it and the step (a resized swarm crashed later, or failed with the standard library's words).
void Replicate::decide(const ControllerInput& input) {
  const std::size_t n = commands_.size();
  try {
    controller_->decide(input, swarm_, rng_, commands_, events_);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const InputError& e) {
    throw InputError(controller_context() + "failed: " + e.what());
  } catch (const std::exception& e) {
    throw std::runtime_error(controller_context() + "failed: " + e.what());
  } catch (...) {
    throw std::runtime_error(controller_context() + "threw something that is not a std::exception");
  }
  const bool same = swarm_.state.size() == n && swarm_.heading.size() == n &&
                    swarm_.leave_time_left.size() == n && swarm_.partner.size() == n;
  if (!same) {
    throw std::runtime_error(controller_context() +
                             "changed the number of entries of the swarm's state (" +
                             std::to_string(n) + " agents): a controller keeps one per agent");
  }
}

void Replicate::update_aggregates() {
  aggregates_.update(
      engine_->neighbours(), swarm_, spec_.robots.detection_radius,
      rules_.partners_only ? AggregateLinks::PartnersOnly : AggregateLinks::Proximity);
}

void Replicate::step() {
  const ControllerInput input{step_, engine_->neighbours(), engine_->reflections(),
                              aggregates_.facts(), growths_by_size_};
  decide(input);
  leave_episodes_.observe_decision(aggregates_, engine_->neighbours(), engine_->positions(),
                                   swarm_.state);
  write_signals(swarm_.state, signals_);  // an agent displays its state
  try {
    events_.encounters += engine_->step(commands_, signals_).encounters;
  } catch (const BadCommand& e) {
    throw std::runtime_error(controller_context() + e.what());
  } catch (const InputError&) {
    throw;  // callers tell these apart by type (exit codes, Python's exceptions)
  } catch (const Interrupted&) {
    throw;
  } catch (const std::system_error&) {
    throw;
  } catch (const std::runtime_error& e) {
    // An engine that cannot go on (a push Box2D would clamp, say): where, to reproduce it.
    throw std::runtime_error("replicate " + std::to_string(index_) + ", moving from step " +
                             std::to_string(step_) + " to " + std::to_string(step_ + 1) + ": " +
                             e.what());
  }
  ++step_;
  update_aggregates();
  if (checking_) check_invariants(*this);
}

SwarmSnapshot Replicate::snapshot() const {
  return {&spec_,
          step_,
          time(),
          engine_->positions(),
          swarm_.state,
          aggregates_.aggregate_of(),
          aggregates_.count()};
}

}  // namespace swarmagg
