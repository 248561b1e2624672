#pragma once
// Lists the agents in one state, in index order: the pass over all N agents that per-step
// bookkeeping starts from. Without branches (states alternate unpredictably along the
// indices), and with SSE2 sixteen agents at a time: one compare gives a bit per agent, and
// each byte of bits indexes a table of where its set bits lie, so that eight indices are
// written by two vector stores and the count advances by the byte's bit count.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/agent_state.hpp"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace swarmagg {

namespace agents_in_state_detail {

// For each byte of bits: the positions of its set bits, lowest first, one per byte.
constexpr std::array<std::uint64_t, 256> kSetBitPositions = [] {
  std::array<std::uint64_t, 256> table{};
  for (unsigned bits = 0; bits < 256; ++bits) {
    unsigned found = 0;
    for (unsigned bit = 0; bit < 8; ++bit) {
      if ((bits >> bit) & 1u) table[bits] |= std::uint64_t{bit} << (8 * found++);
    }
  }
  return table;
}();

constexpr std::array<std::uint8_t, 256> kSetBitCounts = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned bits = 0; bits < 256; ++bits) {
    for (unsigned bit = 0; bit < 8; ++bit) table[bits] += (bits >> bit) & 1u;
  }
  return table;
}();

}  // namespace agents_in_state_detail

// Writes the indices of the agents whose state is `wanted` or `also_wanted`, in increasing
// order, to out[0, count) and returns count. `out` must hold states.size() entries; all of
// them may be written.
inline std::size_t list_agents_in_states(std::span<const AgentState> states, AgentState wanted,
                                         AgentState also_wanted, std::uint32_t* out) {
  const std::size_t n = states.size();
  const AgentState* s = states.data();
  std::size_t count = 0;
  std::size_t i = 0;
#ifdef __SSE2__
  using agents_in_state_detail::kSetBitCounts;
  using agents_in_state_detail::kSetBitPositions;
  const __m128i wanted_bytes = _mm_set1_epi8(static_cast<char>(wanted));
  const __m128i also_wanted_bytes = _mm_set1_epi8(static_cast<char>(also_wanted));
  const __m128i zero = _mm_setzero_si128();
  // Eight agents from `first` whose bits are `bits`: their indices are first + positions.
  // The stores reach out[count + 7] <= first + 7, within the agents seen so far.
  const auto emit_eight = [&](unsigned bits, std::size_t first) {
    const __m128i positions = _mm_unpacklo_epi8(
        _mm_loadl_epi64(reinterpret_cast<const __m128i*>(&kSetBitPositions[bits])), zero);
    const __m128i base = _mm_set1_epi32(static_cast<int>(first));
    auto* to = reinterpret_cast<__m128i*>(out + count);
    _mm_storeu_si128(to, _mm_add_epi32(_mm_unpacklo_epi16(positions, zero), base));
    _mm_storeu_si128(to + 1, _mm_add_epi32(_mm_unpackhi_epi16(positions, zero), base));
    count += kSetBitCounts[bits];
  };
  for (; i + 16 <= n; i += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s + i));
    const auto bits = static_cast<unsigned>(_mm_movemask_epi8(_mm_or_si128(
        _mm_cmpeq_epi8(bytes, wanted_bytes), _mm_cmpeq_epi8(bytes, also_wanted_bytes))));
    emit_eight(bits & 0xffu, i);
    emit_eight(bits >> 8, i + 8);
  }
#endif
  for (; i < n; ++i) {
    out[count] = static_cast<std::uint32_t>(i);
    count += (s[i] == wanted) | (s[i] == also_wanted);
  }
  return count;
}

// The agents whose state is `wanted` (as list_agents_in_states).
inline std::size_t list_agents_in_state(std::span<const AgentState> states, AgentState wanted,
                                        std::uint32_t* out) {
  return list_agents_in_states(states, wanted, wanted, out);
}

}  // namespace swarmagg
