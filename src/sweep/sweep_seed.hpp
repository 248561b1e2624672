#pragma once
// A run's seed is a pure function of the sweep seed, the run's parameter values and its
// replicate index, never of its position in the grid: adding a value to a list, reordering
// the parameters or sharding the sweep leaves every existing run's seed unchanged.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace swarmagg {

using Assignment = std::pair<std::string, std::string>;  // key path, canonical value

// "key=value" lines sorted by key, numbers in std::to_chars' shortest form (0.0005 and
// 5e-04 are one value): the identity of a parameter point.
std::string canonical_point_text(std::vector<Assignment> assignments);
// 64-bit FNV-1a; stable across platforms and compilers (std::hash is not).
std::uint64_t text_hash(const std::string& text);
std::uint64_t sweep_run_seed(std::uint64_t sweep_seed, const std::vector<Assignment>& point,
                             int replicate);

}  // namespace swarmagg
