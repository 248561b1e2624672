// `swarmagg video FRAMES_DIR OUT.mp4`: assembles numbered frames (frame_000000.png, ...) into
// a video with ffmpeg, as `run --video` does; for frames a run, `render` or the live view's
// recording (V) left in a folder.
#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "cli/commands.hpp"
#include "cli/stoppable_video.hpp"
#include "output/output_check.hpp"

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
      check_output_file(options->output, "OUT");
      assemble_video_unless_stopped(options->frames, options->output, {.fps = options->fps});
      std::cout << "video " << options->output << "\n";
      return 0;
    };
  });
}

}  // namespace swarmagg::cli
