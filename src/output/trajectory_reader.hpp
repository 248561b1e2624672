#pragma once
// Reads trajectories.h5 (layout in trajectory_layout.hpp) back: the world that ran, and
// the stored steps of one replicate, one row at a time (memory of one row).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/agent_state.hpp"
#include "core/vec2.hpp"
#include "output/hdf5_file.hpp"

namespace swarmagg {

// One stored step of one replicate.
struct TrajectoryRow {
  std::int64_t step = 0;
  double time = 0.0;
  std::vector<Vec2> positions;
  std::vector<float> heading;  // radians
  std::vector<AgentState> states;
  std::vector<std::int32_t> aggregate;  // -1: in no aggregate
  int noa = 0;                          // aggregates at this step (largest id + 1)
};

class TrajectoryReader {
 public:
  // Throws InputError when the file is missing or not a swarmagg trajectory file.
  explicit TrajectoryReader(const std::filesystem::path& path);

  const std::string& world_text() const { return world_text_; }
  std::int64_t every() const { return every_; }
  std::int64_t agents() const { return agents_; }
  int replicates() const { return replicates_; }

  // The stored steps of `replicate` (InputError for a replicate the file does not hold).
  std::vector<std::int64_t> steps(int replicate) const;
  // Row `row` of `replicate` into `out` (its buffers are reused).
  void read(int replicate, std::int64_t row, TrajectoryRow& out) const;

 private:
  // The replicate's group, its datasets' shapes checked (InputError naming what is wrong).
  h5::Handle replicate_group(int replicate) const;
  void check_shapes(const h5::Handle& group, int replicate) const;
  // read(), HDF5's failures turned into InputError naming the file and `what`.
  template <typename Read>
  auto reading(const std::string& what, Read read) const;

  std::filesystem::path path_;
  h5::Handle file_;
  std::string world_text_;
  std::int64_t every_ = 0;
  std::int64_t agents_ = 0;
  int replicates_ = 0;
  mutable int checked_replicate_ = -1;  // whose shapes check_shapes found right
  // Scratch buffers of read(): the columns as stored.
  mutable std::vector<double> x_, y_;
  mutable std::vector<std::uint8_t> state_;
  mutable std::vector<std::int64_t> step_;
  mutable std::vector<double> time_;
};

}  // namespace swarmagg
