#pragma once
// The video step of `run --video`, `render --video` and `video`: ffmpeg assembles the frames,
// and Ctrl-C (or SIGTERM) at any moment of it, before ffmpeg starts, while it runs or after it
// has finished, leaves no video and ends the command as interrupted (exit 130 or 143).
#include <filesystem>
#include <optional>

#include "render/video.hpp"

namespace swarmagg::cli {

// The options of a `--video` with `--fps` given or not (VideoOptions' default).
VideoOptions video_options(std::optional<double> fps);

void assemble_video_unless_stopped(const std::filesystem::path& frames,
                                   const std::filesystem::path& output, VideoOptions options);

}  // namespace swarmagg::cli
