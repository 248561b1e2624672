#include "render/frame_recorder.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"
#include "render/png_writer.hpp"

namespace swarmagg {
std::vector<std::filesystem::path> frame_files(const std::filesystem::path& dir) {
  static const std::regex kFrame(R"(frame_[0-9]{6,}\.png)");
  std::vector<std::filesystem::path> frames;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kFrame)) {
      frames.push_back(entry.path());
    }
  }
  return frames;
}

namespace {

void remove_old_frames(const std::filesystem::path& dir) {
  for (const auto& path : frame_files(dir)) std::filesystem::remove(path);
}

}  // namespace

std::string FrameRecorder::frame_name(std::int64_t index) {
  char name[48];
  std::snprintf(name, sizeof name, "frame_%06lld.png", static_cast<long long>(index));
  return name;
}

FrameRecorder::FrameRecorder(const WorldSpec& spec, std::filesystem::path dir,
                             FrameRecorderOptions options)
    : dir_(std::move(dir)),
      options_(options),
      renderer_(spec.render.width, spec.render.height),
      width_(spec.render.width),
      height_(spec.render.height) {
  if (options_.compression_level < 0 || options_.compression_level > 9) {
    throw InputError("PNG compression level " + std::to_string(options_.compression_level) +
                     ": expected 0 (fastest) to 9 (smallest)");
  }
  if (options_.queue_capacity < 1 || options_.encoder_threads < 1) {
    throw InputError("frame recorder: queue capacity and encoder threads must be at least 1");
  }
  std::filesystem::create_directories(dir_);
  remove_old_frames(dir_);
  try {
    for (int t = 0; t < options_.encoder_threads; ++t) {
      encoders_.emplace_back([this] { encode_loop(); });
    }
  } catch (...) {  // could not start a thread: stop the ones that did start
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    work_ready_.notify_all();
    for (auto& encoder : encoders_) encoder.join();
    throw;
  }
}

FrameRecorder::~FrameRecorder() {
  try {
    finish();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swarmagg: frames in %s are incomplete: %s\n", dir_.c_str(), e.what());
  }
}

void FrameRecorder::rethrow_error_locked() {
  if (error_ && !error_reported_) {
    error_reported_ = true;
    std::rethrow_exception(error_);
  }
}

void FrameRecorder::record(const SwarmSnapshot& snapshot) {
  enqueue([&](std::span<std::uint8_t> pixels) { renderer_.render(snapshot, pixels); });
}

void FrameRecorder::record_image(std::span<const std::uint8_t> rgba) {
  if (rgba.size() != static_cast<std::size_t>(width_) * height_ * 4) {
    throw std::invalid_argument("frame recorder: an image of " + std::to_string(rgba.size()) +
                                " bytes for " + std::to_string(width_) + "x" +
                                std::to_string(height_) + " frames");
  }
  enqueue(
      [&](std::span<std::uint8_t> pixels) { std::copy(rgba.begin(), rgba.end(), pixels.begin()); });
}

void FrameRecorder::enqueue(const std::function<void(std::span<std::uint8_t>)>& fill) {
  std::vector<std::uint8_t> pixels;
  {
    std::unique_lock lock(mutex_);
    if (finished_) throw std::logic_error("FrameRecorder::record after finish");
    rethrow_error_locked();
    const int max_buffers = options_.queue_capacity + options_.encoder_threads;
    space_free_.wait(
        lock, [&] { return !free_buffers_.empty() || buffers_allocated_ < max_buffers || error_; });
    rethrow_error_locked();
    if (!free_buffers_.empty()) {
      pixels = std::move(free_buffers_.back());
      free_buffers_.pop_back();
    } else {
      ++buffers_allocated_;
    }
  }
  pixels.resize(static_cast<std::size_t>(width_) * height_ * 4);
  try {
    fill(pixels);
  } catch (...) {
    std::lock_guard lock(mutex_);
    free_buffers_.push_back(std::move(pixels));
    throw;
  }
  {
    std::lock_guard lock(mutex_);
    pending_.push_back(Job{next_index_++, std::move(pixels)});
  }
  work_ready_.notify_one();
}

void FrameRecorder::encode_loop() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      work_ready_.wait(lock, [&] { return !pending_.empty() || stopping_; });
      if (pending_.empty()) return;  // stopping and drained
      job = std::move(pending_.front());
      pending_.pop_front();
    }
    try {
      bool failed = false;
      {
        std::lock_guard lock(mutex_);
        failed = static_cast<bool>(error_);
      }
      if (!failed) {
        write_png(dir_ / frame_name(job.index), width_, height_, job.pixels,
                  options_.compression_level);
      }
    } catch (const std::exception& e) {
      std::lock_guard lock(mutex_);
      if (!error_) {
        error_ = std::make_exception_ptr(std::runtime_error(
            "cannot write " + frame_name(job.index) + " in " + dir_.string() + ": " + e.what()));
      }
    }
    {
      std::lock_guard lock(mutex_);
      free_buffers_.push_back(std::move(job.pixels));
    }
    space_free_.notify_one();
  }
}

void FrameRecorder::finish() {
  {
    std::lock_guard lock(mutex_);
    if (finished_) {
      rethrow_error_locked();
      return;
    }
    finished_ = true;
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (auto& encoder : encoders_) encoder.join();
  encoders_.clear();
  std::lock_guard lock(mutex_);
  free_buffers_.clear();
  free_buffers_.shrink_to_fit();
  rethrow_error_locked();
}

}  // namespace swarmagg
