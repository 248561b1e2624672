#include "render/frame_recorder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

#include "core/errors.hpp"
#include "render/frame_renderer.hpp"
#include "render_testing.hpp"

namespace swarmagg {
namespace {

std::set<std::string> names_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    names.insert(e.path().filename().string());
  }
  return names;
}

TEST(FrameRecorder, NamesFramesWithSixDigits) {
  EXPECT_EQ(FrameRecorder::frame_name(0), "frame_000000.png");
  EXPECT_EQ(FrameRecorder::frame_name(123), "frame_000123.png");
  EXPECT_EQ(FrameRecorder::frame_name(1234567), "frame_1234567.png");
}

TEST(FrameRecorder, WritesNumberedFramesOfEachRecordedState) {
  testing::ScratchDir scratch("recorder");
  WorldSpec spec = testing::tiny_world();
  spec.render.width = 160;
  spec.render.height = 120;
  testing::Swarm swarm;
  swarm.spec = &spec;
  swarm.add(5, 20, AgentState::Go);
  const auto dir = scratch.path() / "frames";
  std::vector<std::vector<std::uint8_t>> expected;
  FrameRenderer reference(160, 120);
  {
    FrameRecorderOptions options;
    options.queue_capacity = 2;  // smaller than the number of frames: record() must wait
    FrameRecorder recorder(spec, dir, options);
    for (int f = 0; f < 7; ++f) {
      swarm.positions[0].x = 5.0 + 4.0 * f;  // the state changes right after record()
      swarm.step = f * 10;
      swarm.time = f;
      recorder.record(swarm.snapshot());
      const auto pixels = reference.render(swarm.snapshot());
      expected.emplace_back(pixels.begin(), pixels.end());
    }
    EXPECT_EQ(recorder.frames_recorded(), 7);
    recorder.finish();
    recorder.finish();  // idempotent
  }
  std::set<std::string> want;
  for (int f = 0; f < 7; ++f) want.insert(FrameRecorder::frame_name(f));
  EXPECT_EQ(names_in(dir), want);
  for (int f = 0; f < 7; ++f) {
    const testing::Image image = testing::read_png(dir / FrameRecorder::frame_name(f));
    EXPECT_EQ(image.width, 160);
    EXPECT_EQ(image.height, 120);
    EXPECT_EQ(image.rgba, expected[f]) << "frame " << f;
  }
}

TEST(FrameRecorder, DestructorDrainsTheQueue) {
  testing::ScratchDir scratch("recorder-drain");
  WorldSpec spec = testing::tiny_world();
  spec.render.width = 64;
  spec.render.height = 64;
  const testing::Swarm swarm = testing::random_swarm(spec, 20, 0.0);
  {
    FrameRecorderOptions options;
    options.encoder_threads = 2;
    FrameRecorder recorder(spec, scratch.path(), options);
    for (int f = 0; f < 12; ++f) recorder.record(swarm.snapshot());
  }
  EXPECT_EQ(names_in(scratch.path()).size(), 12u);
  EXPECT_TRUE(std::filesystem::exists(scratch.path() / "frame_000011.png"));
}

TEST(FrameRecorder, RemovesFramesOfAnEarlierRunOnly) {
  testing::ScratchDir scratch("recorder-stale");
  WorldSpec spec = testing::tiny_world();
  spec.render.width = 64;
  spec.render.height = 64;
  for (const char* name : {"frame_000000.png", "frame_000099.png", "notes.txt", "frame_1.png"}) {
    std::ofstream(scratch.path() / name) << "old";
  }
  const testing::Swarm swarm = testing::random_swarm(spec, 5, 0.0);
  {
    FrameRecorder recorder(spec, scratch.path());
    recorder.record(swarm.snapshot());
  }
  EXPECT_EQ(names_in(scratch.path()),
            (std::set<std::string>{"frame_000000.png", "notes.txt", "frame_1.png"}));
  EXPECT_EQ(testing::read_png(scratch.path() / "frame_000000.png").width, 64);
}

TEST(FrameRecorder, ReportsEncoderErrors) {
  testing::ScratchDir scratch("recorder-error");
  WorldSpec spec = testing::tiny_world();
  spec.render.width = 64;
  spec.render.height = 64;
  const testing::Swarm swarm = testing::random_swarm(spec, 5, 0.0);
  const auto dir = scratch.path() / "frames";
  FrameRecorder recorder(spec, dir);
  // Replace the directory with a file: every write fails from now on.
  std::filesystem::remove_all(dir);
  { std::ofstream(dir) << "in the way"; }
  bool thrown = false;
  try {
    for (int f = 0; f < 20; ++f) recorder.record(swarm.snapshot());
    recorder.finish();
  } catch (const std::runtime_error& e) {
    thrown = true;
    EXPECT_NE(std::string(e.what()).find("frame_0000"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(thrown);
}

TEST(FrameRecorder, RejectsBadOptionsAndSizes) {
  testing::ScratchDir scratch("recorder-bad");
  WorldSpec spec = testing::tiny_world();
  FrameRecorderOptions options;
  options.compression_level = 12;
  EXPECT_THROW(FrameRecorder(spec, scratch.path(), options), InputError);
  options = {};
  options.queue_capacity = 0;
  EXPECT_THROW(FrameRecorder(spec, scratch.path(), options), InputError);
  spec.render.width = 4;
  EXPECT_THROW(FrameRecorder(spec, scratch.path()), InputError);
}

}  // namespace
}  // namespace swarmagg
