#pragma once
// Which agents of a kinematic step sleep: those whose step would repeat the last one exactly.
//
// An island is a connected component of the step's candidate pairs (guarded_motion.hpp):
// events happen only between the agents of a pair, so an island's step depends on nothing but
// its own members' positions, commands and signals, their pairs and the fixed limits. An
// island sleeps when
//  - every member is at rest: it did not move during the last step (its position kept every
//    bit), and its command and signal are the ones it had then;
//  - it is the island it was then (the same members: no moving agent came within the pair
//    reach, none left), and the reach is the same;
//  - its last step counted no encounter.
// Then the island's last step was closed (nothing outside it took part) and ran on the very
// inputs this step has, so this step would give the same result: nobody in it moves, and it
// counts no encounter. Waiting members of a packed aggregate whose pull is balanced, and
// those whose pull presses into bodies that halt them at once, sleep this way; they wake as
// soon as a neighbour moves, changes its command or state, or a moving agent comes within
// the reach. Sleepers are then left out of the guarded motion (their velocity is taken as
// zero, which is what they would do) and keep their positions bit for bit.
//
// Islands are found by union-find over the candidate pairs, only when enough agents press
// at rest (moving agents pushing into bodies that halt them: their contact responses are
// what sleep spares; a standing agent costs the guarded motion little). A whole world at rest
// on the same pairs sleeps without labelling: it is one closed island. A moving world is not
// even looked at (its inputs recorded) while the last step's motion left too few agents that
// may press at rest: all its bookkeeping then costs the engine a pass over the agents whose
// motion changed.
#include <cstdint>
#include <span>
#include <vector>

#include "control_interface/motion_command.hpp"
#include "core/agent_array.hpp"
#include "core/vec2.hpp"
#include "engine/kinematic/guarded_motion.hpp"

namespace swarmagg {

// What the engine saw of the last step's motion, to tell whether this step is worth looking
// at (a guess: it never changes who moves, only whether sleep is tried).
struct LastStepRest {
  bool still = true;         // every agent commanded to move stayed where it was
  std::size_t pressing = 0;  // agents commanded to move that stayed (halted at once, or asleep)
};

class SleepingIslands {
 public:
  // Decides who sleeps in the step about to be resolved from `positions` (its start) with
  // `commands` and `signals`, over `pairs` found with pair reach `reach`. `met`: the agents
  // that took part in an encounter during the last step. `same_pairs`: the pairs are those
  // of the last step (nothing moved, the reach stayed), so the islands are too. A world
  // that moved, in which too few agents may press at rest (`last`), is not looked at: it
  // sleeps nobody and records nothing (then the next step cannot sleep anyone either).
  void decide(std::span<const Vec2> positions, std::span<const MotionCommand> commands,
              std::span<const Signal> signals, std::span<const CandidatePair> pairs, double reach,
              std::span<const std::uint32_t> met, bool same_pairs, const LastStepRest& last);
  // Forgets everything: in the next step nobody sleeps (a step resolved without guards).
  void forget();

  bool asleep(std::uint32_t agent) const { return asleep_[agent] != 0; }
  // The agents asleep in this step, in increasing order.
  std::span<const std::uint32_t> sleepers() const { return sleepers_; }
  // Each agent's position at the step's start (what a sleeper keeps).
  Vec2 start_of(std::uint32_t agent) const { return last_position_[agent]; }
  // Which agents left where the step started, bit for bit: none, only agents for which
  // `paired` is false, or (also when this step's start was not recorded: a moving world's
  // step not looked at) some agent for which it is true. Stops at the first of those.
  enum class Moved { Nobody, OnlyUnpaired, Paired };
  template <typename Paired>
  Moved who_moved(std::span<const Vec2> positions, Paired&& paired) const {
    if (!recorded_ || positions.size() != last_position_.size()) return Moved::Paired;
    bool moved = false;
    for (std::uint32_t a = 0; a < positions.size(); ++a) {
      if (same_bits(positions[a], last_position_[a])) continue;
      if (paired(a)) return Moved::Paired;
      moved = true;
    }
    return moved ? Moved::OnlyUnpaired : Moved::Nobody;
  }
  // Whether every agent's command and signal are, bit for bit, those of the last step
  // decided (a world that slept whole then sleeps whole again: decide() is not needed).
  bool inputs_repeat(std::span<const MotionCommand> commands,
                     std::span<const Signal> signals) const;

 private:
  void reset(std::size_t agents);
  // Whether the agent's inputs equal those of the last step (and remembers this step's).
  bool at_rest(std::uint32_t agent, Vec2 position, const MotionCommand& command, Signal signal);
  void label_islands(std::size_t agents, std::span<const CandidatePair> pairs);

  void clear_sleepers();
  void everybody_sleeps(std::size_t agents);

  bool recorded_ = false;  // the last step's inputs were recorded
  bool known_ = false;     // and its islands labelled
  double reach_ = -1.0;
  AgentArray<Vec2> last_position_;
  AgentArray<MotionCommand> last_command_;
  AgentArray<Signal> last_signal_;
  AgentArray<std::uint8_t> rest_;
  AgentArray<std::uint8_t> met_;
  // Islands: each agent's root (the island's lowest member) and the island's size, of this
  // step and of the last.
  AgentArray<std::uint32_t> parent_;
  AgentArray<std::uint32_t> size_;
  AgentArray<std::uint32_t> root_;
  AgentArray<std::uint32_t> last_root_;
  AgentArray<std::uint32_t> last_size_;
  AgentArray<std::uint8_t> island_sleeps_;  // by root
  AgentArray<std::uint8_t> asleep_;
  std::vector<std::uint32_t> sleepers_;
};

}  // namespace swarmagg
