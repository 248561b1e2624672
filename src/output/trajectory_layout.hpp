#pragma once
// The layout of trajectories.h5 (run.trajectories = K > 0), shared by its writer and reader:
//
//   /                      attributes: format, world (the resolved world, the text of
//                          world.resolved.yaml), every (K), agents (N), replicates,
//                          run_seed, seeds (uint64, one generator key per replicate)
//   /replicate_<r>/        attributes: replicate (r), seed; datasets, one row per stored
//                          step (steps 0, K, 2K, ... <= the run's last step), T rows:
//     step      int64   [T]
//     time      float64 [T]
//     x, y      float64 [T, N]   positions, exactly as simulated (wrapped into the arena)
//     heading   float32 [T, N]   radians counter-clockwise from +x
//     state     uint8   [T, N]   0 GO, 1 WAIT, 2 LEAVE, 3 APPROACH (core/agent_state.hpp)
//     aggregate int32   [T, N]   aggregate id 0 .. NOA-1 at that step, -1 for none
//
// Datasets are chunked (kChunkElements elements per chunk, whole rows when they fit),
// byte-shuffled and deflated.
#include <cstdint>
#include <string>

namespace swarmagg::trajectory_layout {

inline constexpr const char* kFileName = "trajectories.h5";
inline constexpr const char* kFormat = "swarmagg-trajectories 1";
inline constexpr std::int64_t kChunkElements = 1 << 16;
inline constexpr int kDeflateLevel = 1;  // most of level 9's gain on shuffled data, far faster

inline std::string group_name(int replicate) {
  return "replicate_" + std::to_string(replicate);
}

// Rows stored for a run of `steps` steps, every `every` steps from step 0.
inline std::int64_t stored_rows(std::int64_t steps, std::int64_t every) {
  return steps / every + 1;
}

// Columns per chunk: whole rows up to kChunkElements agents; rows per chunk: as many rows as
// fill kChunkElements.
inline std::int64_t chunk_columns(std::int64_t agents) {
  return agents < kChunkElements ? agents : kChunkElements;
}
inline std::int64_t chunk_rows(std::int64_t agents, std::int64_t rows) {
  const std::int64_t fit = kChunkElements / chunk_columns(agents);
  return fit < rows ? fit : rows;
}

}  // namespace swarmagg::trajectory_layout
