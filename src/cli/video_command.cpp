// `swarmagg video FRAMES_DIR OUT.mp4`: assembles numbered frames (frame_000000.png, ...) into
// a video with ffmpeg, as `run --video` does; for frames a run, `render` or the live view's
// recording (V) left in a folder.
#include <CLI/CLI.hpp>
#include <iostream>
#include <stdexcept>
#include <string>

#include "cli/commands.hpp"
#include "render/video.hpp"
#include "run/interrupt.hpp"

namespace swarmagg::cli {
namespace {

struct VideoCommandOptions {
  std::string frames;
  std::string output;
  double fps = 25.0;
};

}  // namespace

void add_video_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<VideoCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "video", "Assemble a folder of frames (frame_000000.png, ...) into a video with ffmpeg");
  command->add_option("FRAMES_DIR", options->frames, "Folder of numbered frames")->required();
  command->add_option("OUT", options->output, "The video to write (e.g. out.mp4)")->required();
  command->add_option("--fps", options->fps, "Frames per second (default 25)");
  command->callback([options, &action] {
    action = [options] {
      // Ctrl-C reaches ffmpeg too; with the handlers this process outlives it, removes the
      // half-made video and exits as interrupted (without them the temporary stayed).
      install_interrupt_handlers();
      try {
        assemble_video(options->frames, options->output, options->fps);
      } catch (const std::runtime_error&) {
        throw_if_interrupted();
        throw;
      }
      std::cout << "video " << options->output << "\n";
      return 0;
    };
  });
}

}  // namespace swarmagg::cli
