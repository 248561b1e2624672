#pragma once
// Records a replicate as numbered PNG frames: record() draws the snapshot at once (the
// simulation may change its state right after) and hands the pixels to background encoder
// thread(s), which write frame_000000.png, frame_000001.png, ... (the index of the recorded
// frame, at least 6 digits) into the frames directory. At most queue_capacity frames wait
// for encoding; record() blocks while the queue is full, so memory stays bounded
// ((queue_capacity + encoder_threads) frame buffers of width * height * 4 bytes).
//
// On construction the directory is created and frame_NNNNNN.png files left there by an
// earlier run are removed, so a later video never mixes two runs. The first error on an
// encoder thread (disk full, ...) is rethrown once, by the next record() or by finish();
// frames recorded after it are not written.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "config/world_spec.hpp"
#include "observers/swarm_snapshot.hpp"
#include "render/frame_renderer.hpp"

namespace swarmagg {

// The numbered frames (frame_000000.png, ...) in `dir`, in no particular order.
std::vector<std::filesystem::path> frame_files(const std::filesystem::path& dir);

struct FrameRecorderOptions {
  int compression_level = 1;  // zlib level of the PNGs, 0..9
  int queue_capacity = 4;     // frames drawn but not yet encoded
  int encoder_threads = 1;
};

class FrameRecorder {
 public:
  // Frame size from spec.render.width x height. Throws InputError for bad sizes or options.
  FrameRecorder(const WorldSpec& spec, std::filesystem::path dir,
                FrameRecorderOptions options = {});
  ~FrameRecorder();  // finish(); an error is reported on stderr, not thrown
  FrameRecorder(const FrameRecorder&) = delete;
  FrameRecorder& operator=(const FrameRecorder&) = delete;

  void record(const SwarmSnapshot& snapshot);
  // Queues an image drawn elsewhere (width * height * 4 bytes, RGBA, top-down), as the next
  // frame: the live view records the scene it shows.
  void record_image(std::span<const std::uint8_t> rgba);
  // Waits until every recorded frame is on disk and stops the encoders; idempotent.
  void finish();

  const std::filesystem::path& dir() const { return dir_; }
  std::int64_t frames_recorded() const { return next_index_; }
  static std::string frame_name(std::int64_t index);  // "frame_000123.png"

 private:
  struct Job {
    std::int64_t index = 0;
    std::vector<std::uint8_t> pixels;
  };
  // Takes a free buffer (waiting for one), lets `fill` draw into it, queues it for encoding.
  void enqueue(const std::function<void(std::span<std::uint8_t>)>& fill);
  void encode_loop();
  void rethrow_error_locked();

  std::filesystem::path dir_;
  FrameRecorderOptions options_;
  FrameRenderer renderer_;
  int width_;
  int height_;
  std::int64_t next_index_ = 0;

  std::mutex mutex_;
  std::condition_variable work_ready_;  // encoders wait for jobs
  std::condition_variable space_free_;  // record() waits for a free buffer
  std::deque<Job> pending_;
  std::vector<std::vector<std::uint8_t>> free_buffers_;
  int buffers_allocated_ = 0;
  bool stopping_ = false;
  bool finished_ = false;
  std::exception_ptr error_;
  bool error_reported_ = false;
  std::vector<std::thread> encoders_;
};

}  // namespace swarmagg
