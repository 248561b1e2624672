#pragma once
// What a controller asks of one agent's body for one step. Engines execute these without
// knowing any controller rule: signals are opaque small integers every agent displays
// (its state, as a robot would show an LED colour), and the masks say which displayed
// signals matter to this body.
#include <cstdint>

#include "core/vec2.hpp"

namespace swarmagg {

using Signal = std::uint8_t;  // at most 16 distinct values
// 16 bits keep a command at 24 bytes: the arrays of commands are streamed several times a
// step, which at a million agents is memory traffic, not arithmetic.
using SignalMask = std::uint16_t;

constexpr SignalMask mask_of(Signal s) {
  return static_cast<SignalMask>(1u << s);
}

// Two bodies are solid to each other when either one's blocked_by holds the other's signal
// (both engines and the invariant checks decide by this alone). Without a branch: whether a
// pair is solid is a coin toss to the branch predictor.
constexpr bool solid_pair(SignalMask blocked_by_a, Signal signal_a, SignalMask blocked_by_b,
                          Signal signal_b) {
  return ((blocked_by_a & mask_of(signal_b)) | (blocked_by_b & mask_of(signal_a))) != 0;
}

struct MotionCommand {
  Vec2 velocity;  // desired velocity, u/tu
  // Guarded move: stop at the first moment within the step at which an agent displaying one
  // of these signals comes within the detection radius s.
  SignalMask halt_on = 0;
  // Bodies displaying these signals are solid to this one (contact at distance 2r), and it to
  // them: a pair is solid when either side's mask holds the other's signal. All other bodies
  // pass over it like the paper's point particles.
  SignalMask blocked_by = 0;
  // Bodies displaying these signals push this one away within s (body engines; the
  // kinematic engine leaves avoidance to the commanded velocity).
  SignalMask repelled_by = 0;
};
static_assert(sizeof(MotionCommand) == 24);

}  // namespace swarmagg
