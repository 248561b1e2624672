#include "run/replicate.hpp"

#include <cmath>

#include "run/initial_placement.hpp"
#include "run/invariants.hpp"

namespace swarmagg {

namespace {

// A leaver is held by its aggregate as far as its controller would steer back to it: the
// approach radius of a controller that approaches, else the detection radius.
EpisodeRules episode_rules(const WorldSpec& spec, const ControllerRules& rules) {
  return {.escape_radius = rules.allows(AgentState::Approach) ? spec.controller.approach_radius
                                                              : spec.robots.detection_radius,
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

void Replicate::update_aggregates() {
  aggregates_.update(
      engine_->neighbours(), swarm_, spec_.robots.detection_radius,
      rules_.partners_only ? AggregateLinks::PartnersOnly : AggregateLinks::Proximity);
}

void Replicate::step() {
  const ControllerInput input{step_, engine_->neighbours(), engine_->reflections(),
                              aggregates_.facts(), growths_by_size_};
  controller_->decide(input, swarm_, rng_, commands_, events_);
  leave_episodes_.observe_decision(aggregates_, engine_->neighbours(), engine_->positions(),
                                   swarm_.state);
  write_signals(swarm_.state, signals_);  // an agent displays its state
  events_.encounters += engine_->step(commands_, signals_).encounters;
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
