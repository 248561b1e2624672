#pragma once
// Assembling rendered frames (frame_000000.png, ...) into a video with the ffmpeg program,
// run directly (posix_spawn, arguments passed as a list: no shell, no quoting issues). The
// video is written beside the target and renamed over it when ffmpeg succeeds.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace swarmagg {

struct VideoOptions {
  double fps = 25.0;
  int crf = 20;                   // H.264 quality for .mp4/.mkv/.mov/.m4v (0 best .. 51 worst)
  std::string ffmpeg = "ffmpeg";  // a name searched on PATH, or a path
  // Whether the command was asked to stop (Ctrl-C), asked before ffmpeg starts and before its
  // video replaces the output: a signal that came before ffmpeg was there to receive it, or
  // after it had finished, still leaves no video (std::runtime_error instead).
  std::function<bool()> stop_requested = {};
};

// The executable `name` resolves to (PATH search unless it contains '/'); empty if none.
std::filesystem::path find_program(std::string_view name);

// What a command checks before it renders anything, so that it can refuse a video it could
// not make: InputError for a bad fps/crf, an output without extension, or a kind of video
// this ffmpeg cannot make (it makes a two-frame video of that kind in a hidden folder beside
// the output: about 0.1 s); std::runtime_error when ffmpeg is not installed (the message says how
// to install it). Returns ffmpeg's path.
std::filesystem::path check_video_request(const std::filesystem::path& output,
                                          const VideoOptions& options);
// Throws InputError for a bad fps/crf, an output without extension or a directory without
// frame_000000.png; std::runtime_error when ffmpeg is not installed (the message says how to
// install it), fails (the message carries ffmpeg's own error output) or a stop was requested.
void assemble_video(const std::filesystem::path& frames_dir, const std::filesystem::path& output,
                    double fps);
void assemble_video(const std::filesystem::path& frames_dir, const std::filesystem::path& output,
                    const VideoOptions& options);

}  // namespace swarmagg
