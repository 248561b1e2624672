#include "engine/kinematic/sleeping_islands.hpp"

#include <algorithm>
#include <bit>

namespace swarmagg {
namespace {

// Islands are labelled only when at least one agent in this many presses at rest.
constexpr std::size_t kPressersPerLabelling = 16;

bool same_command(const MotionCommand& a, const MotionCommand& b) {
  return same_bits(a.velocity, b.velocity) & (a.halt_on == b.halt_on) &
         (a.blocked_by == b.blocked_by) & (a.repelled_by == b.repelled_by);
}

// The bits in which two commands and signals differ, folded into one word (zero: the same).
std::uint64_t command_difference(const MotionCommand& a, Signal a_signal, const MotionCommand& b,
                                 Signal b_signal) {
  const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
  const std::uint64_t masks = static_cast<std::uint64_t>(a.halt_on ^ b.halt_on) |
                              static_cast<std::uint64_t>(a.blocked_by ^ b.blocked_by) |
                              static_cast<std::uint64_t>(a.repelled_by ^ b.repelled_by) |
                              static_cast<std::uint64_t>(a_signal ^ b_signal);
  return (bits(a.velocity.x) ^ bits(b.velocity.x)) | (bits(a.velocity.y) ^ bits(b.velocity.y)) |
         masks;
}

}  // namespace

void SleepingIslands::reset(std::size_t agents) {
  last_position_.assign(agents, Vec2{});
  last_command_.assign(agents, MotionCommand{});
  last_signal_.assign(agents, Signal{0});
  rest_.assign(agents, 0);
  parent_.assign(agents, 0u);
  size_.assign(agents, 0u);
  root_.assign(agents, 0u);
  last_root_.assign(agents, 0u);
  last_size_.assign(agents, 0u);
  island_sleeps_.assign(agents, 0);
  asleep_.assign(agents, 0);
  sleepers_.clear();
  known_ = false;
  recorded_ = false;
}

bool SleepingIslands::inputs_repeat(std::span<const MotionCommand> commands,
                                    std::span<const Signal> signals) const {
  if (!recorded_ || commands.size() != last_command_.size()) return false;
  // Without a branch per agent: a world that slept whole nearly always repeats.
  std::uint64_t difference = 0;
  for (std::size_t a = 0; a < commands.size(); ++a) {
    difference |= command_difference(commands[a], signals[a], last_command_[a], last_signal_[a]);
  }
  return difference == 0;
}

void SleepingIslands::clear_sleepers() {
  for (const std::uint32_t agent : sleepers_) asleep_[agent] = 0;
  sleepers_.clear();
}

void SleepingIslands::forget() {
  clear_sleepers();
  known_ = false;
  recorded_ = false;
}

bool SleepingIslands::at_rest(std::uint32_t agent, Vec2 position, const MotionCommand& command,
                              Signal signal) {
  const bool rest = same_bits(position, last_position_[agent]) &
                    same_command(command, last_command_[agent]) & (signal == last_signal_[agent]);
  last_position_[agent] = position;
  last_command_[agent] = command;
  last_signal_[agent] = signal;
  return rest;
}

// Union-find linking the higher root under the lower, so that each island's root is its
// lowest member and, in increasing order, each agent finds its root through its parent's.
void SleepingIslands::label_islands(std::size_t agents, std::span<const CandidatePair> pairs) {
  std::uint32_t* parent = parent_.data();
  for (std::uint32_t a = 0; a < agents; ++a) {
    parent[a] = a;
    size_[a] = 1;
  }
  auto find = [parent](std::uint32_t a) {
    while (parent[a] != a) {
      parent[a] = parent[parent[a]];
      a = parent[a];
    }
    return a;
  };
  for (const CandidatePair& pair : pairs) {
    const std::uint32_t a = find(pair.i), b = find(pair.j);
    if (a == b) continue;
    const std::uint32_t low = std::min(a, b), high = std::max(a, b);
    parent[high] = low;
    size_[low] += size_[high];
  }
  for (std::uint32_t a = 0; a < agents; ++a) {
    root_[a] = parent[a] == a ? a : root_[parent[a]];
  }
}

void SleepingIslands::decide(std::span<const Vec2> positions,
                             std::span<const MotionCommand> commands,
                             std::span<const Signal> signals, std::span<const CandidatePair> pairs,
                             double reach, std::span<const std::uint32_t> met, bool same_pairs,
                             const LastStepRest& last) {
  const std::size_t agents = positions.size();
  if (last_position_.size() != agents) reset(agents);
  // A world that moved, with too few agents that may press at rest, can sleep nobody in this
  // step (not all of it rests); recording it pays only when enough may press in the next.
  if (!last.still && last.pressing * kPressersPerLabelling < agents) return forget();
  const bool same_reach = recorded_ && reach == reach_;
  const bool comparable = known_ && same_reach;
  clear_sleepers();
  std::size_t resting = 0, resting_pressers = 0;
  for (std::uint32_t a = 0; a < agents; ++a) {
    const bool rest = at_rest(a, positions[a], commands[a], signals[a]);
    rest_[a] = rest;
    resting += rest;
    resting_pressers += rest & !is_zero(commands[a].velocity);
  }
  for (const std::uint32_t agent : met) {
    resting -= rest_[agent];
    rest_[agent] = 0;
  }
  reach_ = reach;
  recorded_ = true;
  known_ = false;
  // The whole world at rest on the same pairs is one closed island: all of it sleeps.
  if (resting == agents && same_reach && same_pairs) return everybody_sleeps(agents);
  // Labelling costs a pass over the pairs; it pays when it may spare the contact responses
  // of enough agents pressing at rest (a standing agent costs the guarded motion little).
  if (resting_pressers * kPressersPerLabelling < agents) return;
  known_ = true;
  // The same pairs make the same islands: last step's labels stand (root_ still holds them).
  if (!(comparable && same_pairs)) label_islands(agents, pairs);
  for (std::uint32_t a = 0; a < agents; ++a) island_sleeps_[a] = comparable;
  for (std::uint32_t a = 0; a < agents; ++a) {
    const std::uint32_t root = root_[a];
    const bool same_island = (last_root_[a] == root) & (last_size_[a] == size_[root]);
    island_sleeps_[root] &= static_cast<std::uint8_t>(rest_[a] & same_island);
  }
  for (std::uint32_t a = 0; a < agents; ++a) {
    const std::uint32_t root = root_[a];
    if (island_sleeps_[root]) {
      asleep_[a] = 1;
      sleepers_.push_back(a);
    }
    last_root_[a] = root;
    last_size_[a] = size_[root];
  }
}

void SleepingIslands::everybody_sleeps(std::size_t agents) {
  for (std::uint32_t a = 0; a < agents; ++a) {
    asleep_[a] = 1;
    sleepers_.push_back(a);
  }
}

}  // namespace swarmagg
