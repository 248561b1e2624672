// `swarmagg render RUN_DIR`: draws frames of a stored run from its trajectories.h5, without
// simulating. The frames are those `run --render-every` draws at the same steps, pixel for
// pixel: the same renderer, given the same snapshot (positions, states, aggregate ids, step
// and time exactly as stored) of the same world (the resolved world stored in the file).
#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/frame_output.hpp"
#include "cli/stoppable_video.hpp"
#include "config/world_loader.hpp"
#include "config/world_override.hpp"
#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "output/output_check.hpp"
#include "output/trajectory_layout.hpp"
#include "output/trajectory_reader.hpp"
#include "render/frame_recorder.hpp"
#include "render/staged_frames.hpp"
#include "render/video.hpp"
#include "run/interrupt.hpp"

namespace swarmagg::cli {
namespace {

struct RenderCommandOptions {
  std::string run_dir;
  std::optional<int> every;
  std::optional<std::string> size;
  std::optional<int> replicate;
  std::string out;
  std::string video;
  std::optional<double> fps;  // of --video; VideoOptions' default when not given
  bool quiet = false;
};

// The stored rows are the world's: one every run.trajectories steps, from step 0 to its last.
void check_stored_rows(const TrajectoryReader& reader, const WorldSpec& spec,
                       const std::filesystem::path& file, std::int64_t rows) {
  const std::int64_t expected = trajectory_layout::stored_rows(spec.steps(), reader.every());
  if (reader.every() == spec.run.trajectories && rows == expected) return;
  throw InputError(
      file.string() + ": " + std::to_string(rows) + " rows every " +
      std::to_string(reader.every()) + " steps, but its world stores " +
      std::to_string(trajectory_layout::stored_rows(spec.steps(), spec.run.trajectories)) +
      " every run.trajectories = " + std::to_string(spec.run.trajectories) +
      " steps (the file is damaged)");
}

int render_command(const RenderCommandOptions& options) {
  if (options.fps && options.video.empty()) throw InputError("--fps needs --video FILE");
  const std::filesystem::path file =
      std::filesystem::path(options.run_dir) / trajectory_layout::kFileName;
  const TrajectoryReader reader(file);
  const std::vector<WorldOverride> overrides =
      options.size ? render_size_overrides(*options.size, "--size") : std::vector<WorldOverride>{};
  const WorldSpec spec = load_world_text_with(reader.world_text(), file.string(), overrides);
  if (reader.agents() != spec.robots.count) {
    throw InputError(file.string() + ": attribute 'agents' is " + std::to_string(reader.agents()) +
                     ", but its world has robots.count " + std::to_string(spec.robots.count) +
                     " (the file is damaged)");
  }
  const std::int64_t every = options.every.value_or(reader.every());
  if (every <= 0 || every % reader.every() != 0) {
    throw InputError("--every " + std::to_string(every) + ": expected a positive multiple of " +
                     std::to_string(reader.every()) + ", the steps between stored rows of " +
                     file.string());
  }
  const int replicate = options.replicate.value_or(spec.render.replicate);
  const std::vector<std::int64_t> steps = reader.steps(replicate);
  check_stored_rows(reader, spec, file, static_cast<std::int64_t>(steps.size()));
  const std::filesystem::path folder = options.out.empty()
                                           ? std::filesystem::path(options.run_dir) / "frames"
                                           : std::filesystem::path(options.out);
  check_output_folder(folder, options.out.empty() ? "the frame folder" : "--out");
  if (!options.video.empty()) {
    check_output_file(options.video, "--video");
    check_video_request(options.video, video_options(options.fps));
  }
  install_interrupt_handlers();
  // Drawn aside and moved in once every frame is drawn: Ctrl-C or a failure leaves the frames
  // already in the folder (the run's own, by default) as they were. A killed render's or run's
  // staged frames go first.
  remove_stale_temporaries(folder);
  StagedFrames staged(folder);
  FrameRecorder recorder(spec, staged.staging());
  TrajectoryRow row;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i] % every != 0) continue;
    throw_if_interrupted();
    reader.read(replicate, static_cast<std::int64_t>(i), row);
    recorder.record(SwarmSnapshot{&spec, row.step, row.time, row.positions, row.states,
                                  row.aggregate, row.noa});
  }
  recorder.finish();
  staged.commit();
  if (!options.quiet) {
    std::cout << recorder.frames_recorded() << " frames of replicate " << replicate << " (every "
              << every << " steps) in " << folder.string() << "/\n";
  }
  if (!options.video.empty()) {
    assemble_video_unless_stopped(folder, options.video, video_options(options.fps));
    if (!options.quiet) std::cout << "video " << options.video << "\n";
  }
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<RenderCommandOptions>();
  CLI::App* command = app.add_subcommand(
      "render", "Draw frames of a stored run from its trajectories.h5, without simulating");
  command->add_option("RUN_DIR", options->run_dir, "A run folder holding trajectories.h5")
      ->required();
  command->add_option("--every", options->every,
                      "A frame every K steps (a multiple of the stored steps; default: every "
                      "stored step)");
  command->add_option("--size", options->size, "Frame size WxH (default: the world's render size)");
  command->add_option("--replicate", options->replicate,
                      "Which replicate (default: the world's render.replicate)");
  command->add_option("--out", options->out, "Frame folder (default RUN_DIR/frames)");
  command->add_option("--video", options->video,
                      "Assemble the frames into this video with ffmpeg (e.g. out.mp4)");
  command->add_option("--fps", options->fps, "Frames per second of --video (default 25)");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  command->callback(
      [options, &action] { action = [options] { return render_command(*options); }; });
}

}  // namespace swarmagg::cli
