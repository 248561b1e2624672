#include "output/trajectory_writer.hpp"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <utility>

#include "output/atomic_file.hpp"
#include "output/trajectory_layout.hpp"

namespace swarmagg {
namespace {

namespace layout = trajectory_layout;

template <typename T>
h5::Handle make_dataset(const h5::Handle& group, const char* name, std::int64_t rows,
                        std::int64_t agents) {
  return h5::create_dataset(group, name, h5::native_type<T>(), rows, agents,
                            layout::chunk_rows(agents, rows), layout::chunk_columns(agents),
                            layout::kDeflateLevel);
}

// A replicate's scratch file: ".trajectories.h5.replicate_<r>.<pid>.<n>.tmp" beside the target.
std::filesystem::path scratch_file_for(const std::filesystem::path& target, int replicate) {
  return temporary_beside(target.string() + "." + layout::group_name(replicate));
}

// HDF5 1.10's H5Ocopy crashes on its own error path when the disk fills during a copy (a
// segfault in H5T_close_real, which also leaves every temporary behind), so a copy starts only
// with room for it: the scratch file's size and a quarter more, plus 256 KiB for the
// destination's metadata. Another process may still fill the disk meanwhile; this covers a
// run that fills it itself (checked under hdf5_lock, which every write of the run takes).
void check_room_to_copy(const std::filesystem::path& scratch, const std::filesystem::path& into) {
  std::error_code no_size, no_room;
  const std::uintmax_t size = std::filesystem::file_size(scratch, no_size);
  const std::filesystem::path folder = into.has_parent_path() ? into.parent_path() : ".";
  const std::filesystem::space_info room = std::filesystem::space(folder, no_room);
  if (no_size || no_room) return;  // no figure to go by: HDF5 tries
  const std::uintmax_t needed = size + size / 4 + (std::uintmax_t{1} << 18);
  if (room.available < needed) {
    throw std::runtime_error("HDF5: no room to copy a replicate's trajectory into " +
                             into.string() + " (disk full?): about " + std::to_string(needed) +
                             " bytes needed, " + std::to_string(room.available) + " free");
  }
}

template <typename T>
void write_block(const h5::Handle& dataset, std::int64_t first_row, std::int64_t count,
                 const std::vector<T>& values) {
  h5::write_rows<T>(dataset, first_row, count, std::span<const T>(values));
}

}  // namespace

ReplicateTrajectory::ReplicateTrajectory(TrajectoryWriter& writer,
                                         const std::filesystem::path& scratch, int replicate,
                                         std::uint64_t seed, std::int64_t rows, std::int64_t agents)
    : writer_(&writer),
      replicate_(replicate),
      rows_(rows),
      agents_(agents),
      block_rows_(layout::chunk_rows(agents, rows)) {
  std::lock_guard lock(h5::hdf5_lock());
  scratch_file_ = h5::create_file(scratch.string());
  group_ = h5::create_group(scratch_file_, layout::group_name(replicate));
  h5::write_attribute(group_, "replicate", std::int64_t{replicate});
  const std::uint64_t seeds[1] = {seed};
  h5::write_attribute(group_, "seed", std::span<const std::uint64_t>(seeds));
  step_set_ = h5::create_dataset(group_, "step", h5::native_type<std::int64_t>(), rows, 0,
                                 std::min<std::int64_t>(rows, layout::kChunkElements), 1,
                                 layout::kDeflateLevel);
  time_set_ = h5::create_dataset(group_, "time", h5::native_type<double>(), rows, 0,
                                 std::min<std::int64_t>(rows, layout::kChunkElements), 1,
                                 layout::kDeflateLevel);
  x_set_ = make_dataset<double>(group_, "x", rows, agents);
  y_set_ = make_dataset<double>(group_, "y", rows, agents);
  heading_set_ = make_dataset<float>(group_, "heading", rows, agents);
  state_set_ = make_dataset<std::uint8_t>(group_, "state", rows, agents);
  aggregate_set_ = make_dataset<std::int32_t>(group_, "aggregate", rows, agents);
  const auto values = static_cast<std::size_t>(block_rows_ * agents);
  x_.reserve(values);
  y_.reserve(values);
  heading_.reserve(values);
  state_.reserve(values);
  aggregate_.reserve(values);
}

void ReplicateTrajectory::record(const SwarmSnapshot& snapshot, std::span<const Vec2> heading) {
  if (rows_done_ + static_cast<std::int64_t>(step_.size()) >= rows_) {
    throw std::logic_error("trajectory: more rows recorded than the run has stored steps");
  }
  if (static_cast<std::int64_t>(snapshot.positions.size()) != agents_) {
    throw std::logic_error("trajectory: snapshot of another number of agents");
  }
  step_.push_back(snapshot.step);
  time_.push_back(snapshot.time);
  for (std::int64_t i = 0; i < agents_; ++i) {
    const auto a = static_cast<std::size_t>(i);
    x_.push_back(snapshot.positions[a].x);
    y_.push_back(snapshot.positions[a].y);
    heading_.push_back(static_cast<float>(std::atan2(heading[a].y, heading[a].x)));
    state_.push_back(static_cast<std::uint8_t>(snapshot.states[a]));
    aggregate_.push_back(snapshot.aggregate[a]);
  }
  if (static_cast<std::int64_t>(step_.size()) == block_rows_) flush();
}

void ReplicateTrajectory::flush() {
  const auto count = static_cast<std::int64_t>(step_.size());
  if (count == 0) return;
  {
    std::lock_guard lock(h5::hdf5_lock());
    write_block(step_set_, rows_done_, count, step_);
    write_block(time_set_, rows_done_, count, time_);
    write_block(x_set_, rows_done_, count, x_);
    write_block(y_set_, rows_done_, count, y_);
    write_block(heading_set_, rows_done_, count, heading_);
    write_block(state_set_, rows_done_, count, state_);
    write_block(aggregate_set_, rows_done_, count, aggregate_);
  }
  rows_done_ += count;
  step_.clear();
  time_.clear();
  x_.clear();
  y_.clear();
  heading_.clear();
  state_.clear();
  aggregate_.clear();
}

void ReplicateTrajectory::finish() {
  flush();
  if (rows_done_ != rows_) {
    throw std::logic_error("trajectory: " + std::to_string(rows_done_) + " of " +
                           std::to_string(rows_) + " rows recorded");
  }
  {
    std::lock_guard lock(h5::hdf5_lock());
    // Closed one by one, so that a failing last write (a full disk) is reported.
    for (h5::Handle* object : {&step_set_, &time_set_, &x_set_, &y_set_, &heading_set_, &state_set_,
                               &aggregate_set_, &group_, &scratch_file_}) {
      object->close();
    }
  }
  writer_->replicate_finished(replicate_);
}

TrajectoryWriter::TrajectoryWriter(const WorldSpec& spec, const std::string& world_text,
                                   std::filesystem::path target)
    : target_(std::move(target)),
      rows_(layout::stored_rows(spec.steps(), spec.run.trajectories)),
      agents_(spec.robots.count),
      seeds_(static_cast<std::size_t>(spec.run.replicates), 0),
      scratch_files_(static_cast<std::size_t>(spec.run.replicates)),
      begun_(static_cast<std::size_t>(spec.run.replicates), false),
      finished_(static_cast<std::size_t>(spec.run.replicates), false) {
  if (spec.run.trajectories <= 0)
    throw std::logic_error("TrajectoryWriter without run.trajectories");
  if (target_.has_parent_path()) std::filesystem::create_directories(target_.parent_path());
  temporary_ = temporary_beside(target_);
  std::lock_guard lock(h5::hdf5_lock());
  file_ = h5::create_file(temporary_.string());
  h5::write_attribute(file_, "format", std::string(layout::kFormat));
  h5::write_attribute(file_, "world", world_text);
  h5::write_attribute(file_, "every", std::int64_t{spec.run.trajectories});
  h5::write_attribute(file_, "agents", agents_);
  h5::write_attribute(file_, "replicates", std::int64_t{spec.run.replicates});
  const std::uint64_t run_seed[1] = {spec.run.seed};
  h5::write_attribute(file_, "run_seed", std::span<const std::uint64_t>(run_seed));
}

TrajectoryWriter::~TrajectoryWriter() {
  if (committed_) return;
  try {
    std::lock_guard lock(h5::hdf5_lock());
    file_ = h5::Handle();
  } catch (...) {  // closing a file that is about to be removed: nothing to report
  }
  discard_temporary(temporary_);
  for (const auto& scratch : scratch_files_) {
    if (!scratch.empty()) discard_temporary(scratch);
  }
}

ReplicateTrajectory TrajectoryWriter::begin_replicate(int index, std::uint64_t seed) {
  std::filesystem::path scratch;
  {
    std::lock_guard lock(progress_mutex_);
    const auto i = static_cast<std::size_t>(index);
    if (index < 0 || i >= seeds_.size() || begun_[i]) {
      throw std::logic_error("trajectory: replicate " + std::to_string(index) + " begun twice");
    }
    begun_[i] = true;
    seeds_[i] = seed;
    scratch = scratch_files_[i] = scratch_file_for(target_, index);
  }
  return ReplicateTrajectory(*this, scratch, index, seed, rows_, agents_);
}

void TrajectoryWriter::replicate_finished(int index) {
  std::lock_guard lock(progress_mutex_);
  finished_[static_cast<std::size_t>(index)] = true;
  while (copied_in_ < finished_.size() && finished_[copied_in_]) {
    copy_in(copied_in_);
    ++copied_in_;
  }
}

void TrajectoryWriter::copy_in(std::size_t index) {
  {
    // Under the lock: no other replicate writes between the check and the copy.
    std::lock_guard lock(h5::hdf5_lock());
    check_room_to_copy(scratch_files_[index], temporary_);
    const h5::Handle scratch = h5::open_file_read(scratch_files_[index].string());
    h5::copy_object(scratch, layout::group_name(static_cast<int>(index)), file_);
  }
  discard_temporary(scratch_files_[index]);
}

void TrajectoryWriter::commit() {
  {
    std::lock_guard lock(progress_mutex_);
    if (copied_in_ < begun_.size()) {
      throw std::logic_error("trajectory: replicate " + std::to_string(copied_in_) +
                             (begun_[copied_in_] ? " unfinished" : " missing"));
    }
  }
  {
    std::lock_guard lock(h5::hdf5_lock());
    h5::write_attribute(file_, "seeds", std::span<const std::uint64_t>(seeds_));
    file_.close();
  }
  commit_temporary(temporary_, target_);
  committed_ = true;
}

}  // namespace swarmagg
