// trajectories.h5 written by TrajectoryWriter reads back exactly through TrajectoryReader,
// in the same bytes whatever order the replicates ran in; without commit() nothing is left;
// misuse is refused.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <thread>
#include <vector>

#include "cli/cli_testing.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/trajectory_layout.hpp"
#include "output/trajectory_reader.hpp"
#include "output/trajectory_writer.hpp"

namespace swarmagg {
namespace {

namespace fs = std::filesystem;
using testing::read_all;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("swarmagg-trajectory-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

WorldSpec small_world(int agents, int replicates, double duration, int every) {
  WorldSpec spec;
  spec.robots.count = agents;
  spec.run.replicates = replicates;
  spec.run.duration = duration;  // dt 0.1
  spec.run.trajectories = every;
  return spec;
}

// A made-up state of agent i at step k of replicate r, different everywhere.
struct FakeSwarm {
  std::vector<Vec2> positions, heading;
  std::vector<AgentState> states;
  std::vector<std::int32_t> aggregate;

  SwarmSnapshot at(const WorldSpec& spec, int r, std::int64_t k) {
    const auto n = static_cast<std::size_t>(spec.robots.count);
    positions.resize(n);
    heading.resize(n);
    states.resize(n);
    aggregate.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      positions[i] = {0.1 * static_cast<double>(i) + r + 1e-9 * static_cast<double>(k),
                      1.0 / 3.0 + static_cast<double>(k)};
      const double angle = 0.001 * static_cast<double>(i + static_cast<std::size_t>(k));
      heading[i] = {std::cos(angle), std::sin(angle)};
      states[i] = static_cast<AgentState>((i + static_cast<std::size_t>(k)) % kAgentStateCount);
      aggregate[i] = static_cast<std::int32_t>(i % 3) - 1;
    }
    return {&spec, k, 0.1 * static_cast<double>(k), positions, states, aggregate, 2};
  }
};

ReplicateTrajectory begin(TrajectoryWriter& writer, int r) {
  return writer.begin_replicate(r, 1000u + static_cast<unsigned>(r));
}

void record_step(ReplicateTrajectory& trajectory, const WorldSpec& spec, int r, std::int64_t k) {
  FakeSwarm swarm;
  const SwarmSnapshot snapshot = swarm.at(spec, r, k);  // before heading is read
  trajectory.record(snapshot, swarm.heading);
}

void write_replicate(TrajectoryWriter& writer, const WorldSpec& spec, int r) {
  ReplicateTrajectory trajectory = begin(writer, r);
  for (std::int64_t k = 0; k <= spec.steps(); k += spec.run.trajectories) {
    record_step(trajectory, spec, r, k);
  }
  trajectory.finish();
}

TEST(TrajectoryFile, ReadsBackWhatWasWrittenByParallelReplicates) {
  const fs::path dir = fresh_dir("roundtrip");
  const WorldSpec spec = small_world(7, 3, 10.0, 3);  // 100 steps: rows at 0, 3, ..., 99
  {
    TrajectoryWriter writer(spec, "name: roundtrip\n", dir / "trajectories.h5");
    std::vector<std::thread> threads;
    for (int r = 0; r < 3; ++r) threads.emplace_back([&, r] { write_replicate(writer, spec, r); });
    for (auto& t : threads) t.join();
    EXPECT_FALSE(fs::exists(dir / "trajectories.h5")) << "visible before commit";
    writer.commit();
  }
  const TrajectoryReader reader(dir / "trajectories.h5");
  EXPECT_EQ(reader.world_text(), "name: roundtrip\n");
  EXPECT_EQ(reader.every(), 3);
  EXPECT_EQ(reader.agents(), 7);
  EXPECT_EQ(reader.replicates(), 3);
  for (int r = 0; r < 3; ++r) {
    const auto steps = reader.steps(r);
    ASSERT_EQ(steps.size(), 34u);
    FakeSwarm expected;
    TrajectoryRow row;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const std::int64_t k = 3 * static_cast<std::int64_t>(i);
      EXPECT_EQ(steps[i], k);
      const SwarmSnapshot want = expected.at(spec, r, k);
      reader.read(r, static_cast<std::int64_t>(i), row);
      EXPECT_EQ(row.step, k);
      EXPECT_EQ(row.time, want.time);
      for (std::size_t a = 0; a < 7; ++a) {
        EXPECT_EQ(row.positions[a], want.positions[a]) << "exact doubles, agent " << a;
        EXPECT_EQ(row.states[a], want.states[a]);
        EXPECT_EQ(row.aggregate[a], want.aggregate[a]);
        EXPECT_NEAR(row.heading[a], std::atan2(expected.heading[a].y, expected.heading[a].x), 1e-6);
      }
      EXPECT_EQ(row.noa, 2);
    }
  }
  EXPECT_THROW(reader.steps(3), InputError);
  fs::remove_all(dir);
}

// Replicates begun, recorded and finished in another order (as parallel threads may) write
// the same bytes as one after the other.
TEST(TrajectoryFile, TheOrderReplicatesRunInDoesNotChangeTheFile) {
  const fs::path dir = fresh_dir("order");
  // Rows of 16 Ki agents: a chunk holds 4 rows, so each replicate writes 3 blocks of 11 rows.
  const WorldSpec spec = small_world(16384, 3, 1.0, 1);
  {
    TrajectoryWriter writer(spec, "name: order\n", dir / "in-order.h5");
    for (int r = 0; r < 3; ++r) write_replicate(writer, spec, r);
    writer.commit();
  }
  {
    TrajectoryWriter writer(spec, "name: order\n", dir / "interleaved.h5");
    const int begun[3] = {2, 0, 1};
    std::vector<ReplicateTrajectory> trajectories;
    for (const int r : begun) trajectories.push_back(begin(writer, r));
    for (std::int64_t k = 0; k <= spec.steps(); ++k) {
      for (std::size_t i = 0; i < 3; ++i) record_step(trajectories[i], spec, begun[i], k);
    }
    for (const std::size_t i : {0, 2, 1}) trajectories[i].finish();  // replicates 2, 1, 0
    trajectories.clear();
    writer.commit();
  }
  const std::string in_order = read_all(dir / "in-order.h5");
  EXPECT_FALSE(in_order.empty());
  EXPECT_TRUE(read_all(dir / "interleaved.h5") == in_order) << "the two files differ";
  fs::remove_all(dir);
}

TEST(TrajectoryFile, WithoutCommitNoFileRemains) {
  const fs::path dir = fresh_dir("abandoned");
  const WorldSpec spec = small_world(5, 2, 1.0, 1);
  {
    TrajectoryWriter writer(spec, "name: abandoned\n", dir / "trajectories.h5");
    ReplicateTrajectory trajectory = writer.begin_replicate(0, 1);
    FakeSwarm swarm;
    const SwarmSnapshot snapshot = swarm.at(spec, 0, 0);  // before heading is read
    trajectory.record(snapshot, swarm.heading);
    // Interrupted here: the writer goes without commit().
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "a temporary or partial file was left";
  fs::remove_all(dir);
}

TEST(TrajectoryFile, CommitRefusesMissingOrIncompleteReplicates) {
  const fs::path dir = fresh_dir("incomplete");
  const WorldSpec spec = small_world(5, 2, 1.0, 5);  // 10 steps: rows 0, 5, 10
  TrajectoryWriter writer(spec, "", dir / "trajectories.h5");
  write_replicate(writer, spec, 0);
  EXPECT_THROW(writer.commit(), std::logic_error) << "replicate 1 never began";
  ReplicateTrajectory short_one = writer.begin_replicate(1, 2);
  FakeSwarm swarm;
  const SwarmSnapshot snapshot = swarm.at(spec, 1, 0);  // before heading is read
  short_one.record(snapshot, swarm.heading);
  EXPECT_THROW(short_one.finish(), std::logic_error) << "1 of 3 rows";
  fs::remove_all(dir);
}

TEST(TrajectoryFile, RowsWiderThanAChunkRoundTrip) {
  const fs::path dir = fresh_dir("wide");
  const int agents = static_cast<int>(trajectory_layout::kChunkElements) + 123;
  const WorldSpec spec = small_world(agents, 1, 0.2, 1);  // rows 0, 1, 2
  {
    TrajectoryWriter writer(spec, "", dir / "trajectories.h5");
    write_replicate(writer, spec, 0);
    writer.commit();
  }
  const TrajectoryReader reader(dir / "trajectories.h5");
  TrajectoryRow row;
  reader.read(0, 2, row);
  FakeSwarm expected;
  const SwarmSnapshot want = expected.at(spec, 0, 2);
  ASSERT_EQ(row.positions.size(), static_cast<std::size_t>(agents));
  EXPECT_EQ(row.positions.back(), want.positions.back());
  EXPECT_EQ(row.aggregate[65600], want.aggregate[65600]);
  fs::remove_all(dir);
}

// Damage that only a hand-edited or broken file has: each is refused naming the file and
// what is wrong, where a dataset narrower than the agents was read past its end (a crash,
// or garbage positions drawn) and a missing group was reported as a replicate out of range.
TEST(TrajectoryFile, ReaderRefusesDamagedFilesNamingWhatIsWrong) {
  const fs::path dir = fresh_dir("damaged");
  const WorldSpec spec = small_world(5, 2, 2.0, 4);  // 20 steps: rows at 0, 4, ..., 20
  auto write = [&](const fs::path& file) {
    TrajectoryWriter writer(spec, "name: damaged\n", file);
    for (int r = 0; r < 2; ++r) write_replicate(writer, spec, r);
    writer.commit();
  };
  auto error_of = [](const fs::path& file, int replicate) {
    try {
      const TrajectoryReader reader(file);
      TrajectoryRow row;
      reader.read(replicate, 0, row);
      return std::string("no error");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  auto damage = [](const fs::path& file, const std::function<void(hid_t)>& edit) {
    const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(h5, 0);
    edit(h5);
    H5Fclose(h5);
  };
  auto replace_dataset = [](hid_t h5, const char* path, hid_t type, std::vector<hsize_t> shape) {
    H5Ldelete(h5, path, H5P_DEFAULT);
    const hid_t space = H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr);
    H5Dclose(H5Dcreate2(h5, path, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    H5Sclose(space);
  };
  auto set_attribute = [](hid_t h5, const char* name, std::int64_t value) {
    const hid_t attribute = H5Aopen(h5, name, H5P_DEFAULT);
    H5Awrite(attribute, H5T_NATIVE_INT64, &value);
    H5Aclose(attribute);
  };
  const fs::path file = dir / "t.h5";
  write(file);
  EXPECT_EQ(error_of(file, 1), "no error");
  const std::string name = file.string();

  damage(file, [&](hid_t h5) { replace_dataset(h5, "replicate_1/y", H5T_NATIVE_DOUBLE, {6, 1}); });
  EXPECT_EQ(error_of(file, 1), name +
                                   ": replicate_1/y: shape [6 x 1], expected [6 x 5] (stored "
                                   "rows x the file's 5 agents; the file is damaged)");
  EXPECT_EQ(error_of(file, 0), "no error");
  write(file);
  damage(file, [&](hid_t h5) { replace_dataset(h5, "replicate_0/x", H5T_NATIVE_DOUBLE, {3, 5}); });
  EXPECT_EQ(error_of(file, 0), name +
                                   ": replicate_0/x: shape [3 x 5], expected [6 x 5] (stored "
                                   "rows x the file's 5 agents; the file is damaged)");
  write(file);
  damage(file, [&](hid_t h5) { H5Ldelete(h5, "replicate_0/state", H5P_DEFAULT); });
  EXPECT_EQ(error_of(file, 0), name + ": replicate_0/state: missing (the file is damaged)");
  write(file);
  damage(file, [&](hid_t h5) { H5Ldelete(h5, "replicate_0", H5P_DEFAULT); });
  EXPECT_EQ(error_of(file, 0), name +
                                   ": no group replicate_0, though the file says it holds 2 "
                                   "replicates (the file is damaged)");
  write(file);
  damage(file, [&](hid_t h5) { set_attribute(h5, "every", 0); });
  EXPECT_EQ(error_of(file, 0),
            name +
                ": attribute 'every' is 0: expected a positive whole number (the file is "
                "damaged)");
  // An aggregate id no run of 5 agents has (at most 2 aggregates) would size what draws them.
  write(file);
  damage(file, [&](hid_t h5) {
    std::vector<std::int32_t> ids(6 * 5, -1);
    ids[3] = 1000000000;
    const hid_t dataset = H5Dopen2(h5, "replicate_0/aggregate", H5P_DEFAULT);
    H5Dwrite(dataset, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, ids.data());
    H5Dclose(dataset);
  });
  EXPECT_EQ(error_of(file, 0), name +
                                   ": aggregate id 1000000000 out of range at row 0 (expected -1 "
                                   "to 1 for 5 agents; the file is damaged)");
  // Rows every 3 steps, says the attribute; the steps stored are every 4.
  write(file);
  damage(file, [&](hid_t h5) { set_attribute(h5, "every", 3); });
  EXPECT_THAT([&] { (void)TrajectoryReader(file).steps(0); },
              ::testing::ThrowsMessage<InputError>(
                  name + ": replicate_0/step: row 1 is step 4, expected 3 (rows every 'every' "
                         "steps from 0; the file is damaged)"));
  fs::remove_all(dir);
}

TEST(TrajectoryFile, ReaderRefusesOtherFiles) {
  const fs::path dir = fresh_dir("other");
  EXPECT_THROW(TrajectoryReader(dir / "missing.h5"), InputError);
  write_file_atomic(dir / "text.h5", "not hdf5");
  EXPECT_THROW(TrajectoryReader(dir / "text.h5"), InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace swarmagg
