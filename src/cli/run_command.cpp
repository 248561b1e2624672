#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "analysis/model_errors.hpp"
#include "cli/commands.hpp"
#include "cli/follow_up_commands.hpp"
#include "cli/frame_output.hpp"
#include "cli/progress_option.hpp"
#include "cli/stoppable_video.hpp"
#include "cli/world_options.hpp"
#include "config/world_override.hpp"
#include "controllers/controller_registry.hpp"
#include "core/counted.hpp"
#include "core/errors.hpp"
#include "models/measured_rates.hpp"
#include "models/predictions.hpp"
#include "output/atomic_file.hpp"
#include "output/made_folders.hpp"
#include "output/output_check.hpp"
#include "output/trajectory_layout.hpp"
#include "plot/run_plots.hpp"
#include "rates/rate_outputs.hpp"
#include "rates/rates_text.hpp"
#include "render/staged_frames.hpp"
#include "render/video.hpp"
#include "run/earlier_run.hpp"
#include "run/interrupt.hpp"
#include "run/measured_run.hpp"
#include "run/model_outputs.hpp"
#include "run/placement_sample.hpp"
#include "run/replicate_observer.hpp"
#include "run/run_folder.hpp"
#include "run/timeseries_spool.hpp"
#include "run/trajectory_output.hpp"
#include "run/world_runner.hpp"

namespace swarmagg::cli {
namespace {

struct RunCommandOptions {
  WorldOptions world;
  std::string out;
  bool quiet = false;
  ProgressOption progress;
  bool check = false;
  bool no_model = false;
  bool rates = false;
  bool no_plots = false;
  bool force = false;
  std::optional<int> render_every;
  std::optional<std::string> render_size;
  std::optional<std::string> render_dir;
  std::optional<int> render_replicate;
  std::optional<int> trajectories;
  std::string video;
  std::optional<double> fps;  // of --video; VideoOptions' default when not given
};

// The render flags are shortcuts for render.* world keys, so they land in the resolved world.
void add_render_overrides(const RunCommandOptions& options, WorldOptions& world) {
  auto& typed = world.typed_overrides;
  if (options.render_every)
    typed.push_back(typed_override("render.every", *options.render_every, "--render-every"));
  if (options.render_size) {
    for (WorldOverride& o : render_size_overrides(*options.render_size, "--render-size"))
      typed.push_back(std::move(o));
  }
  if (options.render_dir)
    typed.push_back(typed_override("render.dir", *options.render_dir, "--render-dir"));
  if (options.render_replicate) {
    typed.push_back(
        typed_override("render.replicate", *options.render_replicate, "--render-replicate"));
  }
  if (options.trajectories)
    typed.push_back(typed_override("run.trajectories", *options.trajectories, "--trajectories"));
}

void print_summary(const WorldSpec& spec, const RunResult& result,
                   const std::filesystem::path& out) {
  double noa = 0.0;
  for (const ReplicateOutcome& r : result.replicates) noa += r.final_row.noa;
  const std::string threads = result.step_threads > 1
                                  ? std::to_string(result.threads) + " x " +
                                        std::to_string(result.step_threads) + " threads"
                                  : counted(result.threads, "thread");
  std::cout << spec.name << ": " << counted(spec.run.replicates, "replicate") << " x "
            << spec.steps() << " steps in " << result.wall_seconds << " s on " << threads
            << "; mean final NOA " << noa / spec.run.replicates << "\n"
            << "outputs in " << out.string() << "/\n";
}

bool predictable(const WorldSpec& spec) {
  try {
    check_predictable(spec);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// A world the models cannot describe (say, a partition model of too many agents) still
// keeps its simulation outputs: the run only notes why model.csv is missing. Where the world
// departs from the models' assumptions (walls, say) the run says so beside the model's errors.
void write_predictions(const WorldSpec& spec, const std::filesystem::path& out,
                       const MeasuredTerms* measured, const PlacementSample* sample,
                       bool show_progress, bool quiet) {
  try {
    write_model_outputs(spec, pending_predictions(spec, measured, sample), out, show_progress);
  } catch (const InputError& e) {
    std::cerr << "note: no model.csv: " << e.what() << "\n";
    return;
  }
  if (quiet) return;
  if (const std::string note = no_model_note(spec); !note.empty())
    std::cerr << "note: " << note << "\n";
  for (const std::string& caveat : world_caveats(spec)) std::cerr << "note: " << caveat << "\n";
}

// Plots are a view of the outputs, not an output the run can fail on: without gnuplot, or
// when gnuplot fails on one, the run's data stand and stderr says what is missing.
void draw_plots(const std::filesystem::path& out, bool quiet) {
  if (const std::string reason = plots_unavailable_reason(); !reason.empty()) {
    std::cerr << "note: plots skipped: " << reason << "\n";
    return;
  }
  const PlotOutcome outcome = draw_run_plots(out, out);
  // Ctrl-C reaches gnuplot too: its half-drawn plots are the interruption's, not a full disk's.
  throw_if_interrupted();
  for (const std::string& failure : outcome.failures) std::cerr << "warning: " << failure << "\n";
  if (quiet || outcome.drawn.empty()) return;
  std::cout << "plots:";
  for (const std::filesystem::path& png : outcome.drawn)
    std::cout << " " << png.filename().string();
  std::cout << " (scripts and their CSVs in " << (out / kPlotsFolder).string() << "/)\n";
}

// A frame or video option that would change nothing is refused, as a typo would be: the
// user expects frames (or a video) that the run would not make.
void refuse_idle_render_options(const RunCommandOptions& options, const WorldSpec& spec) {
  if (spec.render.every <= 0) {
    for (const auto& [given, name] :
         {std::pair{!options.video.empty(), "--video"},
          {options.render_size.has_value(), "--render-size"},
          {options.render_dir.has_value(), "--render-dir"},
          {options.render_replicate.has_value(), "--render-replicate"}}) {
      if (given) {
        throw InputError(std::string(name) +
                         " needs frames: give --render-every K (or render.every in the world)");
      }
    }
  }
  if (options.fps && options.video.empty()) throw InputError("--fps needs --video FILE");
}

// Ctrl-C after the simulation's outputs were written (a complete run: its world.resolved.yaml
// is there) and before its rates or model were: says so, and which commands add them. The
// measured variants and a measured start need the rates first.
std::string what_is_left(const std::filesystem::path& out, const RunCommandOptions& options,
                         bool rates_measured) {
  const bool rates_wanted = options.rates || (rates_measured && !options.no_model);
  const std::string commands = rates_and_model_commands(out, rates_wanted, !options.no_model);
  if (commands.empty()) return "";
  return "swarmagg: the simulation's outputs in " + out.string() +
         "/ are complete; what follows them is not. To add it: " + commands + "\n";
}

struct RatesAndModel {
  std::optional<MeasuredTerms> measured;
  std::vector<RateRow> rows;
};

// What follows the simulation's outputs: the rates it measured (rates.csv with --rates) and
// the model predictions with their errors (model.csv, model-timeseries/, summary.json).
RatesAndModel write_rates_and_model(const WorldSpec& spec, const RunCommandOptions& options,
                                    const MeasuredRun& run, const std::filesystem::path& out) {
  // The models' start, for the rates' `initial` rows and the models (unless they refuse the
  // world: then it would be drawn for nothing, seconds for a large swarm).
  const bool wanted = run.rates || (!options.no_model && predictable(spec));
  std::string no_start;  // why the start could not be sampled (the run's outputs stand)
  const std::optional<PlacementSample> start =
      wanted ? placement_start_or_reason(spec, 0, no_start) : std::nullopt;
  const PlacementSample* sample = start ? &*start : nullptr;
  RatesAndModel written;
  if (run.rates) {
    written.rows = measured_rate_rows(spec, *run.rates, sample);
    if (options.rates && !no_start.empty())
      std::cerr << "note: " << second_order_initial_note(no_start) << "\n";
    if (options.rates) {
      // Without gnuplot the run's own "plots skipped" note says it once for all plots.
      const bool draw = !options.no_plots && plots_unavailable_reason().empty();
      write_rate_outputs(spec, *run.rates, written.rows, out,
                         draw ? RatePlots::Draw : RatePlots::ScriptsOnly);
    }
    written.measured = measured_terms(written.rows);
  }
  if (!options.no_model) {
    if (!no_start.empty()) {
      std::cerr << "note: no model.csv: " << no_start << "\n";
    } else {
      options.progress.phase(options.quiet, spec.name,
                             "computing the model predictions (model.csv)");
      write_predictions(spec, out, written.measured ? &*written.measured : nullptr, sample,
                        options.progress.shown(options.quiet), options.quiet);
    }
    write_model_errors(out);
  }
  return written;
}

// The run writes these files and folders once it has simulated: a folder where a file goes
// (or a file where a folder goes) would fail it after the run, which would be lost.
void refuse_obstructed_outputs(const std::filesystem::path& out) {
  std::error_code error;
  for (const char* name :
       {"world.resolved.yaml", "timeseries.csv", "summary.json", "partitions.csv", "model.csv",
        "rates.csv", "rates.json", "trajectories.h5", "noa.png", "states.png", "sizes.png",
        "partitions.png"}) {
    if (std::filesystem::exists(out / name, error) &&
        !std::filesystem::is_regular_file(out / name, error)) {
      throw InputError(
          (out / name).string() +
          " is not a file, and the run writes one there: remove it, or pass --out DIR");
    }
  }
  for (const char* name : {"model-timeseries", "plots"}) {
    if (std::filesystem::exists(out / name, error) &&
        !std::filesystem::is_directory(out / name, error)) {
      throw InputError((out / name).string() +
                       " is not a folder, and the run writes one there: remove it, or pass --out "
                       "DIR");
    }
  }
}

// Every output path is checked before the first step: a long run must not be lost to a
// folder it cannot write.
void check_outputs(const WorldSpec& spec, const RunCommandOptions& options,
                   const std::filesystem::path& out, const std::filesystem::path& frames) {
  // A killed run leaves its rows' temporaries in `out` (made when a run starts): garbage of a
  // process that is gone, not an earlier run to keep, so it does not make the folder refused.
  remove_stale_temporaries(out);
  if (!options.force) refuse_to_replace(out, "an earlier run?", "its run");
  refuse_obstructed_outputs(out);
  // A killed run's temporaries are garbage (they would only count against the disk the new
  // run needs): gone before it starts, from every folder a run writes into.
  if (options.force) {
    for (const std::filesystem::path& folder : {out / "plots", out / "model-timeseries", frames})
      remove_stale_temporaries(folder);
  }
  check_output_folder(out, options.out.empty() ? "the run folder" : "--out");
  if (spec.render.every > 0) {
    check_output_folder(frames, options.render_dir ? "--render-dir" : "the frame folder");
    // A killed run's staged frames (render/staged_frames.hpp), in the frame folder.
    remove_stale_temporaries(frames);
  }
  if (!options.video.empty()) {
    check_output_file(options.video, "--video");
    check_video_request(options.video, video_options(options.fps));
  }
}

int run_command(const RunCommandOptions& options) {
  WorldOptions world = options.world;
  add_render_overrides(options, world);
  const WorldSpec spec = world.load();
  const bool out_given = !options.out.empty();
  const std::filesystem::path out =
      out_given ? std::filesystem::path(options.out) : default_run_folder(spec);
  const std::filesystem::path frames = frames_folder(spec, out, out_given);
  refuse_idle_render_options(options, spec);
  check_outputs(spec, options, out, frames);
  if (const std::string note = spec.rounded_duration_note(); !note.empty() && !options.quiet)
    std::cerr << "note: " << note << "\n";
  install_interrupt_handlers();
  // The run's files are written into `out` while it runs (timeseries.csv's replicates,
  // trajectories): a run that fails or is interrupted leaves no folder made for them.
  const MadeFolders made(out);
  const RemovedOnFailure made_only_for_this_run(made);
  TimeseriesSpool timeseries(out / "timeseries.csv", spec.run.replicates);
  RunOptions run_options;
  run_options.progress = options.progress.shown(options.quiet);
  run_options.check = options.check;
  run_options.timeseries = &timeseries;
  const auto trajectories = trajectory_writer(spec, out);
  // Drawn aside and moved into the frame folder once the simulation is complete: an earlier
  // run's frames stay whole until then, as its other outputs do.
  std::optional<StagedFrames> staged_frames;
  if (spec.render.every > 0) staged_frames.emplace(frames);
  run_options.observers =
      both_observers(frame_observers(spec, staged_frames ? staged_frames->staging() : frames),
                     trajectory_observers(trajectories.get(), spec.run.trajectories));
  const MeasuredRun run = run_world_measuring(spec, run_options, options.rates);
  const RunResult& result = run.result;
  // First: a move that fails then leaves the earlier run's other outputs as they were.
  if (staged_frames) staged_frames->commit();
  if (options.force) {
    for (const std::string& failure : clear_earlier_run(out))
      std::cerr << "warning: cannot remove the earlier run's " << failure << "\n";
  }
  // Before world.resolved.yaml, which marks the folder complete; a file of an earlier run
  // that stored trajectories would not belong to this one.
  if (trajectories) {
    trajectories->commit();
  } else {
    std::filesystem::remove(out / trajectory_layout::kFileName);
  }
  write_run_folder(spec, result, out, options.world.changes(), &timeseries);
  RatesAndModel after;
  try {
    after = write_rates_and_model(spec, options, run, out);
  } catch (const Interrupted&) {
    std::cerr << what_is_left(out, options, run.rates.has_value());
    throw;
  }
  const std::vector<RateRow>& rows = after.rows;
  const std::optional<MeasuredTerms>& measured = after.measured;
  if (!options.quiet && options.rates) {
    for (const std::string& line : rate_summary_lines(rows)) std::cout << line << "\n";
    if (controller_rules(spec).model != ModelFamily::Encounters)
      std::cout << measured_variant_note(spec, *measured) << "\n";
  }
  if (!options.quiet) print_summary(spec, result, out);
  if (!options.no_plots) {
    options.progress.phase(options.quiet, spec.name, "drawing the plots (gnuplot)");
    draw_plots(out, options.quiet);
  }
  if (spec.render.every > 0 && !options.quiet)
    std::cout << "frames in " << frames.string() << "/\n";
  if (trajectories && !options.quiet) {
    std::cout << "trajectories every " << spec.run.trajectories << " steps in "
              << trajectories->target().string() << "\n";
  }
  if (!options.video.empty()) {
    assemble_video_unless_stopped(frames, options.video, video_options(options.fps));
    if (!options.quiet) std::cout << "video " << options.video << "\n";
  }
  return 0;
}

}  // namespace

void add_run_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<RunCommandOptions>();
  CLI::App* command = app.add_subcommand("run", "Simulate a world's replicates and write outputs");
  options->world.add_to(*command);
  command->add_option("--out", options->out, "Output folder (default runs/<world name>)");
  command->add_option("--render-every", options->render_every,
                      "Render a PNG frame every K steps (render.every)");
  command->add_option("--render-size", options->render_size, "Frame size WxH, e.g. 800x800");
  command->add_option("--render-dir", options->render_dir,
                      "Frame folder (default renders/<world name>, or <out>/frames with --out)");
  command->add_option("--render-replicate", options->render_replicate,
                      "Which replicate to render (default 0)");
  command->add_option("--trajectories", options->trajectories,
                      "Store every agent's state every K steps in <out>/trajectories.h5 "
                      "(run.trajectories; 0 = off)");
  command->add_option("--video", options->video,
                      "Assemble the frames into this video with ffmpeg (e.g. out.mp4)");
  command->add_option("--fps", options->fps, "Frames per second of --video (default 25)");
  command->add_flag("--quiet", options->quiet, kQuietHelp);
  options->progress.add_to(*command);
  command->add_flag("--no-model", options->no_model,
                    "Skip the macroscopic predictions (model.csv) beside the run");
  command->add_flag("--rates", options->rates,
                    "Also measure every model term (rates.csv, rates.json, plots) and add the "
                    "`measured` model variants to model.csv");
  command->add_flag("--no-plots", options->no_plots,
                    "Skip the plots (noa.png, states.png, ... drawn with gnuplot)");
  command->add_flag("--force", options->force,
                    "Replace the run in an existing, non-empty output folder");
  command->add_flag("--check", options->check,
                    "Check invariants after every step (always on in Debug builds)");
  command->callback([options, &action] { action = [options] { return run_command(*options); }; });
}

}  // namespace swarmagg::cli
