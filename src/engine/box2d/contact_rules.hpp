#pragma once
// The engine's side of Box2D's callbacks. The contact filter applies MotionCommand's signal
// rule (two bodies are solid to each other iff either one's blocked_by holds the other's
// signal; everything else passes through, like the paper's point particles). The listener
// turns sensor begin/end events into the SensorLinks, counts first contacts within s
// (encounters) and executes guarded moves: a body whose halt_on holds the signal of an agent
// that just came within s stops before the next solver pass. Near the torus seam one pair
// of agents can touch through two solid fixture pairs (the bodies and their images); the
// pre-solve hook keeps only the one that involves the lower-numbered agent's own disc, so
// every pair is one constraint, as in mid-arena.
#include <box2d/box2d.h>

#include <cstdint>
#include <vector>

#include "control_interface/motion_command.hpp"
#include "engine/box2d/periodic_body.hpp"
#include "engine/box2d/sensor_links.hpp"

namespace swarmagg::box2d {

// What each agent displays and asks for during the current step.
struct AgentControls {
  std::vector<Signal> signal;
  std::vector<SignalMask> blocked_by;
  std::vector<SignalMask> halt_on;
  std::vector<SignalMask> repelled_by;
  std::vector<std::uint8_t> halted;  // stopped by a guarded move during this step

  void resize(std::size_t n) {
    signal.assign(n, 0);
    blocked_by.assign(n, 0);
    halt_on.assign(n, 0);
    repelled_by.assign(n, 0);
    halted.assign(n, 0);
  }
  bool solid(AgentId a, AgentId b) const {
    return solid_pair(blocked_by[a], signal[a], blocked_by[b], signal[b]);
  }
};

class ContactRules final : public b2ContactFilter, public b2ContactListener {
 public:
  ContactRules(AgentControls& controls, SensorLinks& links, std::vector<PeriodicBody>& bodies)
      : controls_(controls), links_(links), bodies_(bodies) {}

  bool ShouldCollide(b2Fixture* a, b2Fixture* b) override;
  void BeginContact(b2Contact* contact) override;
  void EndContact(b2Contact* contact) override;
  void PreSolve(b2Contact* contact, const b2Manifold* old_manifold) override;

  // Encounters and halts are acted on only while a step runs (not for the initial overlaps).
  void start_step() {
    stepping_ = true;
    encounters_ = 0;
  }
  std::uint64_t finish_step() {
    stepping_ = false;
    return encounters_;
  }

 private:
  void halt(AgentId agent);

  AgentControls& controls_;
  SensorLinks& links_;
  std::vector<PeriodicBody>& bodies_;
  bool stepping_ = false;
  std::uint64_t encounters_ = 0;
};

}  // namespace swarmagg::box2d
