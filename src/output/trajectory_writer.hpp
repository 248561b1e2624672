#pragma once
// Writes trajectories.h5 (layout in trajectory_layout.hpp) while replicates run in parallel.
// The file is built under a temporary name beside the target and renamed over it by
// commit(), so an interrupted run leaves no half-written .h5: without commit() the
// destructor removes the temporary.
//
// Memory stays bounded: each replicate keeps one chunk's worth of rows (about
// trajectory_layout::kChunkElements values per column) and writes a block of rows when it
// fills. Replicates write under h5::hdf5_lock(), one at a time.
//
// The same bytes for any number of threads: HDF5 puts a chunk wherever the file ends when
// the chunk is written, so replicates writing into one file would lay it out in the order
// the threads happened to run. Each replicate therefore writes a scratch file of its own
// beside the target, and the writer copies the replicates into the file in replicate order,
// each as soon as every earlier one is in: the file is made by the same calls in the same
// order whatever the threads did. Preallocating every replicate's datasets up front
// (H5D_ALLOC_TIME_EARLY) would not do: a deflated chunk's size is known only once written,
// and HDF5 then moves it to the end of the file. Holding a replicate's rows in memory until
// its turn would hold whole trajectories. The copy moves the compressed chunks as they are:
// the cost is writing them twice, and on disk the scratch files of replicates finished ahead
// of an earlier one.
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "config/world_spec.hpp"
#include "core/agent_state.hpp"
#include "core/vec2.hpp"
#include "observers/swarm_snapshot.hpp"
#include "output/hdf5_file.hpp"

namespace swarmagg {

class TrajectoryWriter;

// One replicate's datasets and its buffer of rows not yet written.
class ReplicateTrajectory {
 public:
  ReplicateTrajectory(ReplicateTrajectory&&) = default;
  ~ReplicateTrajectory() = default;

  // Stores one step: the snapshot's positions, states and aggregate ids, and the headings.
  void record(const SwarmSnapshot& snapshot, std::span<const Vec2> heading);
  // Writes the buffered rows and hands the replicate to the writer; throws unless every row
  // of the replicate was recorded.
  void finish();

 private:
  friend class TrajectoryWriter;
  ReplicateTrajectory(TrajectoryWriter& writer, const std::filesystem::path& scratch, int replicate,
                      std::uint64_t seed, std::int64_t rows, std::int64_t agents);
  void flush();

  TrajectoryWriter* writer_;
  int replicate_;
  std::int64_t rows_;
  std::int64_t agents_;
  std::int64_t block_rows_;     // rows written at once (one chunk's rows)
  std::int64_t rows_done_ = 0;  // rows written to the file
  h5::Handle scratch_file_;     // declared before what it holds, so closed after it
  h5::Handle group_;
  h5::Handle step_set_, time_set_, x_set_, y_set_, heading_set_, state_set_, aggregate_set_;
  std::vector<std::int64_t> step_;
  std::vector<double> time_, x_, y_;
  std::vector<float> heading_;
  std::vector<std::uint8_t> state_;
  std::vector<std::int32_t> aggregate_;
};

class TrajectoryWriter {
 public:
  // Creates the temporary file with the root attributes; `world_text` is the resolved world.
  TrajectoryWriter(const WorldSpec& spec, const std::string& world_text,
                   std::filesystem::path target);
  ~TrajectoryWriter();  // removes the temporary unless committed
  TrajectoryWriter(const TrajectoryWriter&) = delete;
  TrajectoryWriter& operator=(const TrajectoryWriter&) = delete;

  // The datasets of replicate `index` (thread-safe; one call per replicate).
  ReplicateTrajectory begin_replicate(int index, std::uint64_t seed);
  // Writes the seeds, closes the file and renames it over the target. Every replicate's
  // ReplicateTrajectory must have finished and been destroyed.
  void commit();

  const std::filesystem::path& target() const { return target_; }

 private:
  friend class ReplicateTrajectory;
  // Called by each replicate's finish(), its scratch file closed: copies into the file every
  // finished replicate whose predecessors are all in, in replicate order.
  void replicate_finished(int index);
  void copy_in(std::size_t index);  // one replicate's group, then its scratch file goes

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  std::int64_t rows_;
  std::int64_t agents_;
  std::vector<std::uint64_t> seeds_;
  std::vector<std::filesystem::path> scratch_files_;  // per replicate, once begun
  std::vector<bool> begun_, finished_;
  std::size_t copied_in_ = 0;  // replicates 0 .. copied_in_ - 1 are in the file
  std::mutex progress_mutex_;  // guards the members above, held while copying in
  h5::Handle file_;
  bool committed_ = false;
};

}  // namespace swarmagg
