#include "core/agents_in_state.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace swarmagg {
namespace {

// The plain definition the listing must agree with.
std::vector<std::uint32_t> listed_one_by_one(const std::vector<AgentState>& states,
                                             AgentState wanted, AgentState also_wanted) {
  std::vector<std::uint32_t> indices;
  for (std::uint32_t i = 0; i < states.size(); ++i) {
    if (states[i] == wanted || states[i] == also_wanted) indices.push_back(i);
  }
  return indices;
}

std::vector<std::uint32_t> listed_one_by_one(const std::vector<AgentState>& states,
                                             AgentState wanted) {
  return listed_one_by_one(states, wanted, wanted);
}

std::vector<std::uint32_t> listed(const std::vector<AgentState>& states, AgentState wanted) {
  std::vector<std::uint32_t> out(states.size(), 0xdeadbeef);
  out.resize(list_agents_in_state(states, wanted, out.data()));
  return out;
}

std::vector<std::uint32_t> listed(const std::vector<AgentState>& states, AgentState wanted,
                                  AgentState also_wanted) {
  std::vector<std::uint32_t> out(states.size(), 0xdeadbeef);
  out.resize(list_agents_in_states(states, wanted, also_wanted, out.data()));
  return out;
}

TEST(AgentsInState, ListsTheAgentsInOneStateInIndexOrder) {
  const std::vector<AgentState> states = {AgentState::Go, AgentState::Wait, AgentState::Wait,
                                          AgentState::Leave, AgentState::Wait};
  EXPECT_EQ(listed(states, AgentState::Wait), (std::vector<std::uint32_t>{1, 2, 4}));
  EXPECT_EQ(listed(states, AgentState::Approach), std::vector<std::uint32_t>{});
}

// Every length around the 16-agent blocks and every mix of states, so that each byte of
// bits (and both halves of a block, and the tail) is met.
TEST(AgentsInState, AgreesWithOneByOneAtEveryLengthAndMix) {
  std::uint64_t x = 12345;
  for (std::size_t n = 0; n <= 70; ++n) {
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<AgentState> states(n);
      for (AgentState& s : states) {
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        s = static_cast<AgentState>((x >> 33) % kAgentStateCount);
      }
      for (int wanted = 0; wanted < kAgentStateCount; ++wanted) {
        const auto state = static_cast<AgentState>(wanted);
        ASSERT_EQ(listed(states, state), listed_one_by_one(states, state)) << "n = " << n;
        for (int also = 0; also < kAgentStateCount; ++also) {
          const auto also_state = static_cast<AgentState>(also);
          ASSERT_EQ(listed(states, state, also_state), listed_one_by_one(states, state, also_state))
              << "n = " << n << ", states " << wanted << " and " << also;
        }
      }
    }
  }
}

TEST(AgentsInState, ListsTheAgentsInEitherOfTwoStates) {
  const std::vector<AgentState> states = {AgentState::Go, AgentState::Wait, AgentState::Approach,
                                          AgentState::Leave, AgentState::Go};
  EXPECT_EQ(listed(states, AgentState::Go, AgentState::Approach),
            (std::vector<std::uint32_t>{0, 2, 4}));
}

TEST(AgentsInState, ListsEveryAgentWhenAllShareTheState) {
  const std::vector<AgentState> states(40, AgentState::Wait);
  EXPECT_EQ(listed(states, AgentState::Wait).size(), 40u);
  EXPECT_EQ(listed(states, AgentState::Go).size(), 0u);
}

}  // namespace
}  // namespace swarmagg
