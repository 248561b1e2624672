#include "cli/stoppable_video.hpp"

#include "run/interrupt.hpp"

namespace swarmagg::cli {

VideoOptions video_options(std::optional<double> fps) {
  VideoOptions video;
  if (fps) video.fps = *fps;
  return video;
}

// Ctrl-C reaches ffmpeg too; with the handlers this process outlives it and removes the
// half-made video (without them the temporary stayed). The error a stop leaves ends the
// command as interrupted (cli/app.cpp).
void assemble_video_unless_stopped(const std::filesystem::path& frames,
                                   const std::filesystem::path& output, VideoOptions options) {
  install_interrupt_handlers();
  options.stop_requested = [] { return interrupt_signal() != 0; };
  assemble_video(frames, output, options);
}

}  // namespace swarmagg::cli
