#include "view/view_session.hpp"

#include <algorithm>
#include <chrono>
#include <ostream>
#include <utility>

#include "core/counted.hpp"
#include "core/errors.hpp"
#include "models/predictions.hpp"
#include "run/placement_sample.hpp"
#include "run/state_hash.hpp"

namespace swarmagg {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The NOA curve of the world's chosen expected-value model variant, without the variant's
// extra values or the other variants (a long world's noise floors alone kept the window from
// opening: 10 s for the demo world over 10^5 tu); none when the world has no model (or one the
// models cannot compute).
std::vector<NoaPoint> model_curve(const WorldSpec& spec) {
  WorldSpec expected = spec;
  expected.model.stochastic_replicates = 0;
  std::vector<NoaPoint> curve;
  try {
    for (const PendingVariant& variant : pending_world_predictions(expected, nullptr, 0)) {
      if (!variant.header.chosen || variant.header.stochastic) continue;
      const auto add_point = [&](const ModelRow& row) {
        if (row.noa) curve.push_back({static_cast<double>(row.step) * spec.engine.dt, *row.noa});
      };
      variant.walk_rows(add_point, {}, Extras::Skipped);
      break;
    }
  } catch (const InputError&) {
    curve.clear();
  }
  return curve;
}

}  // namespace

ViewSession::ViewSession(WorldSpec spec, int replicate, std::ostream& out)
    : spec_(std::make_unique<WorldSpec>(std::move(spec))),
      index_(replicate),
      out_(out),
      control_(spec_->steps(), spec_->engine.dt) {
  if (replicate < 0 || replicate >= spec_->run.replicates) {
    throw InputError("--replicate " + std::to_string(replicate) + ": expected 0 to " +
                     std::to_string(spec_->run.replicates - 1) + " (run.replicates is " +
                     std::to_string(spec_->run.replicates) + ")");
  }
  model_noa_ = model_curve(*spec_);
  restart();
}

ViewSession::~ViewSession() = default;

void ViewSession::restart() {
  replicate_.reset();  // it refers to the spec, which a reseed changes
  replicate_ = std::make_unique<Replicate>(*spec_, index_);
  control_.restart();
  wall_seconds_ = 0.0;
  const auto states = replicate_->swarm().state;
  previous_state_.assign(states.begin(), states.end());
  state_since_.assign(states.size(), 0);
  last_transition_.assign(states.size(), std::nullopt);
  noa_history_.clear();
  noa_history_.push_back({0.0, static_cast<double>(replicate_->aggregates().count())});
  trail_.clear();
  trail_frames_ = 0;
}

void ViewSession::observe_step() {
  const std::int64_t step = replicate_->steps_done();
  const auto& states = replicate_->swarm().state;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i] == previous_state_[i]) continue;
    last_transition_[i] = StateTransition{previous_state_[i], states[i], step};
    previous_state_[i] = states[i];
    state_since_[i] = step;
  }
  if (step % std::max<std::int64_t>(1, spec_->run.record_every) == 0) {
    noa_history_.push_back(
        {replicate_->time(), static_cast<double>(replicate_->aggregates().count())});
  }
  // Trails keep a position per agent every simulated time unit (or every step if longer).
  const auto every = std::max<std::int64_t>(1, std::llround(1.0 / spec_->engine.dt));
  if (scene_.trails && step % every == 0) {
    const auto positions = replicate_->engine().positions();
    if (trail_frames_ == kTrailFrames) {
      trail_.erase(trail_.begin(), trail_.begin() + static_cast<std::ptrdiff_t>(positions.size()));
      --trail_frames_;
    }
    trail_.insert(trail_.end(), positions.begin(), positions.end());
    ++trail_frames_;
  }
}

void ViewSession::step(std::int64_t n) {
  const auto start = Clock::now();
  for (std::int64_t k = 0; k < n; ++k) {
    replicate_->step();
    observe_step();
    if (after_step) after_step();
  }
  wall_seconds_ += seconds_since(start);
}

std::int64_t ViewSession::advance_frame(double frame_seconds, double budget_seconds) {
  const std::int64_t wanted = control_.steps_for_frame(replicate_->steps_done(), frame_seconds);
  const auto start = Clock::now();
  std::int64_t taken = 0;
  while (taken < wanted) {
    step(1);
    ++taken;
    if (control_.took(replicate_->steps_done())) {
      const double noa = replicate_->aggregates().count();
      out_ << spec_->name << ": " << counted(1, "replicate") << " x " << replicate_->steps_done()
           << " steps in " << wall_seconds_ << " s on " << counted(1, "thread")
           << "; mean final NOA " << noa << std::endl;
      break;
    }
    if (control_.pace() == Pace::Fastest && (taken & 15) == 0 &&
        seconds_since(start) > budget_seconds) {
      break;
    }
  }
  return taken;
}

void ViewSession::set_overlay(Overlay overlay, bool on) {
  const OverlayScope scope = on ? OverlayScope::All : OverlayScope::None;
  switch (overlay) {
    case Overlay::Detection:
      scene_.detection = scope;
      break;
    case Overlay::Approach:
      scene_.approach = scope;
      break;
    case Overlay::Links:
      scene_.links = on;
      break;
    case Overlay::Neighbours:
      scene_.neighbour_links = on;
      break;
    case Overlay::Trails:
      scene_.trails = on;
      if (!on) {
        trail_.clear();
        trail_frames_ = 0;
      }
      break;
    case Overlay::Ghosts:
      scene_.ghosts = on;
      break;
    case Overlay::Contacts:
      scene_.contacts = on;
      break;
    case Overlay::Tints:
      scene_.tints = on;
      break;
  }
}

void ViewSession::apply(const ViewCommand& command) {
  switch (command.action) {
    case ViewAction::Step:
      step(command.count);
      break;
    case ViewAction::Play:
      control_.play();
      break;
    case ViewAction::Pause:
      control_.pause();
      break;
    case ViewAction::TogglePlay:
      control_.toggle();
      break;
    case ViewAction::Speed:
      control_.set_steps_per_frame(command.count);
      break;
    case ViewAction::Select: {
      const auto n = static_cast<std::int64_t>(replicate_->swarm().size());
      if (command.count >= n) {
        throw InputError("select " + std::to_string(command.count) +
                         ": the world has agents 0 to " + std::to_string(n - 1));
      }
      scene_.selected = static_cast<std::int32_t>(command.count);
      break;
    }
    case ViewAction::Colour:
      scene_.colour = command.colour;
      break;
    case ViewAction::Overlay:
      set_overlay(command.overlay, command.on);
      break;
    case ViewAction::Panel:
      panel_ = command.on;
      break;
    case ViewAction::Screenshot:
      screenshot_ = command.path;
      break;
    case ViewAction::Hash:
      out_ << hash_line() << std::endl;
      break;
    case ViewAction::Quit:
      quit_ = true;
      break;
    case ViewAction::Reset:
      restart();
      break;
    case ViewAction::Reseed:
      replicate_.reset();
      ++spec_->run.seed;
      restart();
      break;
    case ViewAction::Record:
      record_ = command.on;
      break;
    case ViewAction::Fit:
      scene_.zoom = 1.0;
      scene_.centre.reset();
      follow = false;
      break;
  }
}

SceneExtras ViewSession::extras() const {
  return {trail_, trail_frames_};
}

std::optional<AgentDetails> ViewSession::details(std::int32_t agent) const {
  const auto n = static_cast<std::int32_t>(replicate_->swarm().size());
  if (agent < 0 || agent >= n) return std::nullopt;
  AgentDetails d;
  d.id = agent;
  d.position = spec_->arena.geometry().wrap(replicate_->engine().positions()[agent]);
  d.heading = replicate_->swarm().heading[agent];
  d.state = replicate_->swarm().state[agent];
  d.time_in_state =
      static_cast<double>(replicate_->steps_done() - state_since_[agent]) * spec_->engine.dt;
  const auto& states = replicate_->swarm().state;
  const auto neighbours = replicate_->engine().neighbours().of(static_cast<AgentId>(agent));
  for (const Neighbour& nb : neighbours) {
    if (nb.distance <= spec_->robots.detection_radius) d.neighbours.push_back(nb.id);
  }
  if (d.state == AgentState::Approach) {
    for (const Neighbour& nb : neighbours) {
      if (nb.distance > spec_->controller.approach_radius) break;
      if (states[nb.id] != AgentState::Leave) {
        d.approaching = nb.id;
        break;
      }
    }
  }
  d.aggregate = replicate_->aggregates().aggregate_of()[agent];
  d.aggregate_size = replicate_->aggregates().size_of_agent()[agent];
  d.last_transition = last_transition_[agent];
  return d;
}

std::vector<std::int32_t> ViewSession::state_counts() const {
  std::vector<std::int32_t> counts(kAgentStateCount, 0);
  for (const AgentState s : replicate_->swarm().state) ++counts[static_cast<int>(s)];
  return counts;
}

std::string ViewSession::hash_line() const {
  return "state-hash " + state_hash_text(state_hash(*replicate_)) + " step " +
         std::to_string(replicate_->steps_done());
}

std::optional<std::string> ViewSession::take_screenshot_request() {
  auto request = std::move(screenshot_);
  screenshot_.reset();
  return request;
}

std::optional<bool> ViewSession::take_record_request() {
  return std::exchange(record_, std::nullopt);
}

}  // namespace swarmagg
