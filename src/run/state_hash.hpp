#pragma once
// A fingerprint of one replicate's state: every agent's position, heading and controller
// state, bit for bit, in agent order (FNV-1a, 64 bits, over their bytes). Two replicates
// with the same hash are in the same state, whoever stepped them: summary.json writes it for
// each replicate as `final_state_hash`, and the Python module's Simulation.state_hash() gives
// it at any step, so a replicate stepped by hand can be checked against a run.
#include <cstdint>
#include <string>

namespace swarmagg {

class Replicate;

std::uint64_t state_hash(const Replicate& replicate);
// The form summary.json writes: 16 lowercase hexadecimal digits.
std::string state_hash_text(std::uint64_t hash);

}  // namespace swarmagg
