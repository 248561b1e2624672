#include "render/video.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "core/errors.hpp"
#include "render/frame_recorder.hpp"
#include "render_testing.hpp"

namespace swarmagg {
namespace {

void record_frames(const std::filesystem::path& dir, int count, int width = 96, int height = 64) {
  WorldSpec spec = testing::tiny_world();
  spec.render.width = width;
  spec.render.height = height;
  testing::Swarm swarm = testing::random_swarm(spec, 10, 0.0);
  FrameRecorder recorder(spec, dir);
  for (int f = 0; f < count; ++f) {
    swarm.positions[0].x = 2.0 * f;
    recorder.record(swarm.snapshot());
  }
}

std::string head(const std::filesystem::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

TEST(FindProgram, FindsShellOnPathAndNothingForNonsense) {
  EXPECT_FALSE(find_program("sh").empty());
  EXPECT_TRUE(find_program("swarmagg-no-such-program-xyz").empty());
  EXPECT_TRUE(find_program("/no/such/dir/ffmpeg").empty());
  EXPECT_TRUE(find_program("").empty());
}

TEST(AssembleVideo, SaysHowToInstallFfmpegWhenItIsMissing) {
  testing::ScratchDir scratch("video-missing");
  record_frames(scratch.path(), 1);
  VideoOptions options;
  options.ffmpeg = "swarmagg-no-such-ffmpeg";
  try {
    assemble_video(scratch.path(), scratch.path() / "out.mp4", options);
    FAIL() << "expected an error";
  } catch (const InputError&) {
    FAIL() << "a missing tool is not bad input";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("apt-get install ffmpeg"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "out.mp4"));
}

TEST(AssembleVideo, RejectsBadInput) {
  testing::ScratchDir scratch("video-bad");
  EXPECT_THROW(assemble_video(scratch.path(), scratch.path() / "out.mp4", 25.0), InputError)
      << "no frames";
  record_frames(scratch.path(), 1);
  EXPECT_THROW(assemble_video(scratch.path(), scratch.path() / "out.mp4", 0.0), InputError);
  EXPECT_THROW(assemble_video(scratch.path(), scratch.path() / "out.mp4", -3.0), InputError);
  EXPECT_THROW(assemble_video(scratch.path(), scratch.path() / "out", 25.0), InputError);
  VideoOptions options;
  options.crf = 99;
  EXPECT_THROW(assemble_video(scratch.path(), scratch.path() / "out.mp4", options), InputError);
}

TEST(AssembleVideo, RefusesFramesWithAGap) {
  testing::ScratchDir scratch("video-gap");
  record_frames(scratch.path(), 4);
  std::filesystem::remove(scratch.path() / "frame_000002.png");
  try {
    assemble_video(scratch.path(), scratch.path() / "out.mp4", 25.0);
    FAIL() << "a video of the frames before the gap was made";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("frame_000002.png is missing but 1 later frames exist"),
              std::string::npos)
        << e.what();
  }
}

// ffmpeg exits 0 when the disk fills while it writes the trailer, saying so on stderr: that is
// a failure, and its unplayable file is not left behind.
TEST(AssembleVideo, AnErrorFfmpegReportsIsAFailureWhateverItsExitStatus) {
  testing::ScratchDir scratch("video-silent-failure");
  record_frames(scratch.path() / "frames", 2);
  const auto fake = scratch.path() / "ffmpeg";
  std::ofstream(fake) << "#!/bin/sh\nfor last; do :; done\necho partial > \"$last\"\n"
                         "echo 'Error writing trailer: No space left on device' >&2\nexit 0\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  VideoOptions options;
  options.ffmpeg = fake.string();
  try {
    assemble_video(scratch.path() / "frames", scratch.path() / "out.mp4", options);
    FAIL() << "reported success";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  for (const auto& entry : std::filesystem::directory_iterator(scratch.path())) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "frames" || name == "ffmpeg") << "left behind: " << name;
  }
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "out.mp4"));
}

// A kind of video ffmpeg cannot make is found before any frame is drawn (it was found after
// the whole run).
TEST(CheckVideoRequest, RefusesAKindOfVideoFfmpegCannotMake) {
  if (find_program("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  testing::ScratchDir scratch("video-kind");
  EXPECT_NO_THROW(check_video_request(scratch.path() / "ok.mp4", VideoOptions{}));
  for (const char* output : {"out.xyz", "out.png"}) {  // no such container; one frame only
    try {
      check_video_request(scratch.path() / output, VideoOptions{});
      FAIL() << "accepted " << output;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("ffmpeg cannot make a"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(std::filesystem::is_empty(scratch.path())) << "the probe left something";
}

// A stop asked for before ffmpeg started (it never got the signal) or after it finished
// leaves no video and no temporary: the command ends as interrupted, with nothing written.
TEST(AssembleVideo, AStopBeforeOrAfterFfmpegLeavesNoVideo) {
  if (find_program("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  for (const int stop_at_ask : {1, 2}) {
    testing::ScratchDir scratch("video-stopped");
    const auto frames = scratch.path() / "frames";
    record_frames(frames, 3);
    int asked = 0;
    VideoOptions options;
    options.stop_requested = [&] { return ++asked == stop_at_ask; };
    EXPECT_THROW(assemble_video(frames, scratch.path() / "out.mp4", options), std::runtime_error);
    EXPECT_EQ(asked, stop_at_ask);
    for (const auto& entry : std::filesystem::directory_iterator(scratch.path()))
      EXPECT_EQ(entry.path().filename(), "frames") << "left " << entry.path();
  }
}

TEST(AssembleVideo, MakesAnMp4FromTheFrames) {
  if (find_program("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  // A directory name with characters a shell or ffmpeg's pattern syntax would misread.
  testing::ScratchDir scratch("video mp4 $(echo no) 100%");
  const auto frames = scratch.path() / "frames";
  record_frames(frames, 5, 97, 63);  // odd sides must be padded for yuv420p
  const auto output = scratch.path() / "out dir" / "swarm.mp4";
  assemble_video(frames, output, 10.0);
  ASSERT_TRUE(std::filesystem::exists(output));
  EXPECT_GT(std::filesystem::file_size(output), 500u);
  EXPECT_EQ(head(output, 8).substr(4), "ftyp");  // an ISO media file
  EXPECT_FALSE(std::filesystem::exists("no"));
  std::size_t entries = 0;  // no temporary file left beside the video
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(output.parent_path())) {
    ++entries;
  }
  EXPECT_EQ(entries, 1u);
}

TEST(AssembleVideo, ReportsFfmpegFailuresWithItsMessage) {
  if (find_program("ffmpeg").empty()) GTEST_SKIP() << "ffmpeg is not installed";
  testing::ScratchDir scratch("video-fail");
  record_frames(scratch.path(), 2);
  // A container ffmpeg does not know: it fails, the error says so, no video appears.
  try {
    assemble_video(scratch.path(), scratch.path() / "bad.notavideo", 25.0);
    FAIL() << "expected ffmpeg to fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("ffmpeg failed"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(scratch.path() / "bad.notavideo"));
}

}  // namespace
}  // namespace swarmagg
