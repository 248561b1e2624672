#include "output/trajectory_reader.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/errors.hpp"
#include "output/trajectory_layout.hpp"

namespace swarmagg {
namespace {

namespace layout = trajectory_layout;

// The datasets of a replicate: one value per stored row, or one per row and agent.
constexpr const char* kRowDatasets[] = {"step", "time"};
constexpr const char* kAgentDatasets[] = {"x", "y", "heading", "state", "aggregate"};

std::string shape_text(const std::vector<std::int64_t>& shape) {
  std::string text;
  for (const std::int64_t n : shape) text += (text.empty() ? "" : " x ") + std::to_string(n);
  return "[" + text + "]";
}

}  // namespace

// HDF5's own failures (a damaged chunk, a dataset that will not open) name neither the file
// nor what was read; bad input, not a fault of swarmagg's.
template <typename Read>
auto TrajectoryReader::reading(const std::string& what, Read read) const {
  try {
    return read();
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw InputError(path_.string() + ": " + what + ": " + e.what() + " (the file is damaged)");
  }
}

TrajectoryReader::TrajectoryReader(const std::filesystem::path& path) : path_(path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw InputError(path.string() +
                     ": no trajectory file (run with --trajectories K or run.trajectories: K)");
  }
  std::lock_guard lock(h5::hdf5_lock());
  try {
    file_ = h5::open_file_read(path.string());
    if (h5::read_string_attribute(file_, "format") != layout::kFormat) throw std::runtime_error("");
    world_text_ = h5::read_string_attribute(file_, "world");
    every_ = h5::read_int_attribute(file_, "every");
    agents_ = h5::read_int_attribute(file_, "agents");
    replicates_ = static_cast<int>(h5::read_int_attribute(file_, "replicates"));
  } catch (const std::runtime_error&) {
    throw InputError(path.string() +
                     ": not a swarmagg trajectory file (expected attribute format '" +
                     layout::kFormat + "')");
  }
  for (const auto& [name, value] : {std::pair{"every", every_}, std::pair{"agents", agents_},
                                    std::pair{"replicates", std::int64_t{replicates_}}}) {
    if (value < 1) {
      throw InputError(path.string() + ": attribute '" + name + "' is " + std::to_string(value) +
                       ": expected a positive whole number (the file is damaged)");
    }
  }
}

// Every dataset of the replicate has one row per stored step, and those of the agents one
// column per agent: a damaged file would otherwise be read past its buffers.
void TrajectoryReader::check_shapes(const h5::Handle& group, int replicate) const {
  const std::string where = path_.string() + ": " + layout::group_name(replicate) + "/";
  std::int64_t rows = -1;
  auto check = [&](const char* name, bool per_agent) {
    if (!h5::has_child(group, name))
      throw InputError(where + name + ": missing (the file is damaged)");
    const std::vector<std::int64_t> shape = h5::dataset_shape(h5::open_dataset(group, name));
    if (rows < 0) rows = shape.size() == 1 ? shape[0] : 0;  // `step` gives the stored rows
    const std::vector<std::int64_t> expected =
        per_agent ? std::vector<std::int64_t>{rows, agents_} : std::vector<std::int64_t>{rows};
    if (shape != expected) {
      throw InputError(where + name + ": shape " + shape_text(shape) + ", expected " +
                       shape_text(expected) + " (stored rows" +
                       (per_agent ? " x the file's " + std::to_string(agents_) + " agents" : "") +
                       "; the file is damaged)");
    }
  };
  for (const char* name : kRowDatasets) check(name, false);
  for (const char* name : kAgentDatasets) check(name, true);
  checked_replicate_ = replicate;
}

h5::Handle TrajectoryReader::replicate_group(int replicate) const {
  const std::string name = layout::group_name(replicate);
  if (replicate < 0 || replicate >= replicates_) {
    throw InputError(path_.string() + ": no replicate " + std::to_string(replicate) +
                     " (the file holds replicates 0.." + std::to_string(replicates_ - 1) + ")");
  }
  if (!h5::has_child(file_, name)) {
    throw InputError(path_.string() + ": no group " + name + ", though the file says it holds " +
                     std::to_string(replicates_) + " replicates (the file is damaged)");
  }
  h5::Handle group = h5::open_group(file_, name);
  if (checked_replicate_ != replicate) check_shapes(group, replicate);
  return group;
}

std::vector<std::int64_t> TrajectoryReader::steps(int replicate) const {
  std::lock_guard lock(h5::hdf5_lock());
  const std::string name = layout::group_name(replicate) + "/step";
  std::vector<std::int64_t> values = reading(name, [&] {
    const h5::Handle group = replicate_group(replicate);
    const h5::Handle steps = h5::open_dataset(group, "step");
    std::vector<std::int64_t> read;
    h5::read_rows(steps, 0, h5::dataset_shape(steps)[0], read);
    return read;
  });
  // Rows are stored every `every` steps from step 0: a step off that grid would be drawn (or
  // skipped) as another.
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] == static_cast<std::int64_t>(i) * every_) continue;
    throw InputError(path_.string() + ": " + name + ": row " + std::to_string(i) + " is step " +
                     std::to_string(values[i]) + ", expected " +
                     std::to_string(static_cast<std::int64_t>(i) * every_) +
                     " (rows every 'every' steps from 0; the file is damaged)");
  }
  return values;
}

void TrajectoryReader::read(int replicate, std::int64_t row, TrajectoryRow& out) const {
  std::lock_guard lock(h5::hdf5_lock());
  reading(layout::group_name(replicate) + " row " + std::to_string(row), [&] {
    const h5::Handle group = replicate_group(replicate);
    h5::read_rows(h5::open_dataset(group, "step"), row, 1, step_);
    h5::read_rows(h5::open_dataset(group, "time"), row, 1, time_);
    h5::read_rows(h5::open_dataset(group, "x"), row, 1, x_);
    h5::read_rows(h5::open_dataset(group, "y"), row, 1, y_);
    h5::read_rows(h5::open_dataset(group, "heading"), row, 1, out.heading);
    h5::read_rows(h5::open_dataset(group, "state"), row, 1, state_);
    h5::read_rows(h5::open_dataset(group, "aggregate"), row, 1, out.aggregate);
  });
  out.step = step_[0];
  out.time = time_[0];
  out.positions.resize(x_.size());
  out.states.resize(state_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) {
    out.positions[i] = {x_[i], y_[i]};
    if (state_[i] >= kAgentStateCount) {
      throw InputError(path_.string() + ": agent state " + std::to_string(state_[i]) +
                       " out of range at row " + std::to_string(row));
    }
    out.states[i] = static_cast<AgentState>(state_[i]);
  }
  // Aggregates have two members or more: ids run from 0 below N / 2 (-1: in none). Another id
  // would size what draws the aggregates.
  const auto aggregates = static_cast<std::int32_t>(agents_ / 2);
  for (const std::int32_t id : out.aggregate) {
    if (id >= -1 && id < aggregates) continue;
    throw InputError(path_.string() + ": aggregate id " + std::to_string(id) +
                     " out of range at row " + std::to_string(row) + " (expected -1 to " +
                     std::to_string(aggregates - 1) + " for " + std::to_string(agents_) +
                     " agents; the file is damaged)");
  }
  const auto largest = std::max_element(out.aggregate.begin(), out.aggregate.end());
  out.noa = largest == out.aggregate.end() ? 0 : std::max(0, *largest + 1);
}

}  // namespace swarmagg
