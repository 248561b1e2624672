#pragma once
// A fingerprint of a replicate's state: the exact bits of every agent's position and heading
// and its controller state, in agent order (FNV-1a, 64 bits, stable across compilers). Two
// replicates that went through the same steps from the same world and seed have equal
// hashes; summary.json stores it per replicate as final_state_hash, and `view`'s `hash`
// command prints it, so a viewed run can be checked against a batch run.
#include <cstdint>
#include <string>

#include "run/replicate.hpp"

namespace swarmagg {

std::uint64_t state_hash(const Replicate& replicate);

// 16 lower-case hex digits.
std::string state_hash_text(std::uint64_t hash);

}  // namespace swarmagg
