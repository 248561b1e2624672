#include "render/video.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "output/atomic_file.hpp"
#include "render/frame_recorder.hpp"
#include "render/png_writer.hpp"

extern char** environ;

namespace swarmagg {
namespace {

bool executable(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// ffmpeg's image2 demuxer reads '%' in the input name as a pattern: escape the directory.
std::string escape_percent(const std::string& s) {
  std::string out;
  for (const char c : s) {
    out += c;
    if (c == '%') out += '%';
  }
  return out;
}

std::string fps_text(double fps) {
  char text[64];
  std::snprintf(text, sizeof text, "%.10g", fps);
  return text;
}

struct SpawnResult {
  int status = 0;
  std::string errors;  // the tail of the child's stderr
};

SpawnResult run(const std::filesystem::path& program, const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
    throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawned != 0) {
    ::close(pipe_fds[0]);
    throw std::runtime_error("cannot run " + program.string() + ": " + std::strerror(spawned));
  }

  SpawnResult result;
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (got > 0) {
      result.errors.append(buffer, static_cast<std::size_t>(got));
      if (result.errors.size() > 8192) result.errors.erase(0, result.errors.size() - 4096);
    } else if (got == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(pipe_fds[0]);
  while (::waitpid(pid, &result.status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("cannot wait for " + program.string());
  }
  return result;
}

std::string describe_status(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  return "status " + std::to_string(status);
}

// The frames ffmpeg's pattern reads are frame_000000.png on, up to the first missing
// number: a gap would silently end the video there, so it is refused, naming the gap.
void check_frames_contiguous(const std::filesystem::path& frames_dir) {
  std::vector<long> numbers;
  for (const auto& entry : std::filesystem::directory_iterator(frames_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() != 16 || name.rfind("frame_", 0) != 0 || name.substr(12) != ".png") continue;
    const std::string digits = name.substr(6, 6);
    if (std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }))
      numbers.push_back(std::stol(digits));
  }
  std::sort(numbers.begin(), numbers.end());
  for (std::size_t k = 0; k < numbers.size(); ++k) {
    if (numbers[k] != static_cast<long>(k)) {
      throw InputError(frames_dir.string() + ": " +
                       FrameRecorder::frame_name(static_cast<std::int64_t>(k)) +
                       " is missing but " + std::to_string(numbers.size() - k) +
                       " later frames exist; the video would end at the gap");
    }
  }
}

}  // namespace

std::filesystem::path find_program(std::string_view name) {
  if (name.empty()) return {};
  if (name.find('/') != std::string_view::npos) {
    return executable(name) ? std::filesystem::path(name) : std::filesystem::path();
  }
  const char* path = std::getenv("PATH");
  const std::string dirs = path != nullptr ? path : "/usr/local/bin:/usr/bin:/bin";
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = dirs.find(':', start);
    std::string dir =
        dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (dir.empty()) dir = ".";
    const auto candidate = std::filesystem::path(dir) / name;
    if (executable(candidate)) return candidate;
    if (end == std::string::npos) return {};
    start = end + 1;
  }
}

void assemble_video(const std::filesystem::path& frames_dir, const std::filesystem::path& output,
                    double fps) {
  VideoOptions options;
  options.fps = fps;
  assemble_video(frames_dir, output, options);
}

namespace {

// The checks of check_video_request that need no ffmpeg run; returns ffmpeg's path.
std::filesystem::path video_program(const std::filesystem::path& output,
                                    const VideoOptions& options) {
  if (!std::isfinite(options.fps) || options.fps <= 0.0 || options.fps > 1000.0) {
    throw InputError("video frame rate " + fps_text(options.fps) +
                     ": expected a number of frames per second in (0, 1000]");
  }
  if (options.crf < 0 || options.crf > 51) {
    throw InputError("video quality (crf) " + std::to_string(options.crf) +
                     ": expected 0 (best) to 51 (worst)");
  }
  if (output.extension().empty() || output.stem().empty()) {
    throw InputError("video output '" + output.string() +
                     "' needs a file name with an extension, e.g. swarm.mp4");
  }
  const std::filesystem::path program = find_program(options.ffmpeg);
  if (program.empty()) {
    throw std::runtime_error("cannot assemble a video: '" + options.ffmpeg +
                             "' is not installed (or not on PATH). Install it with `sudo "
                             "apt-get install ffmpeg` (Debian/Ubuntu)");
  }
  return program;
}

std::string trimmed(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

// ffmpeg's arguments to make `made` from the frames (its extension picks the container).
std::vector<std::string> ffmpeg_arguments(const VideoOptions& options,
                                          const std::filesystem::path& frames_dir,
                                          const std::filesystem::path& made) {
  const std::string extension = lower(made.extension().string());
  std::vector<std::string> args{options.ffmpeg,
                                "-nostdin",
                                "-hide_banner",
                                "-loglevel",
                                "error",
                                "-y",
                                "-framerate",
                                fps_text(options.fps),
                                "-start_number",
                                "0",
                                "-i",
                                escape_percent(frames_dir.string()) + "/frame_%06d.png"};
  const bool h264 =
      extension == ".mp4" || extension == ".mkv" || extension == ".mov" || extension == ".m4v";
  if (h264) {
    // yuv420p (what players expect) needs even sides: pad odd frames by one pixel.
    for (const char* a : {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                          "yuv420p", "-crf"}) {
      args.emplace_back(a);
    }
    args.push_back(std::to_string(options.crf));
    if (extension != ".mkv") {
      args.emplace_back("-movflags");
      args.emplace_back("+faststart");
    }
  }
  args.push_back(made.string());
  return args;
}

// Runs ffmpeg to make `made`; when it fails, `made` is removed and the error names `video`.
void make_video(const std::filesystem::path& program, const VideoOptions& options,
                const std::filesystem::path& frames_dir, const std::filesystem::path& made,
                const std::filesystem::path& video) {
  const SpawnResult result = run(program, ffmpeg_arguments(options, frames_dir, made));
  // ffmpeg runs with -loglevel error, so anything it says is an error; some (a trailer that
  // did not fit on a full disk) leave it exiting 0 with an unplayable file.
  if (!WIFEXITED(result.status) || WEXITSTATUS(result.status) != 0 || !result.errors.empty()) {
    discard_temporary(made);
    const bool exited_zero = WIFEXITED(result.status) && WEXITSTATUS(result.status) == 0;
    throw std::runtime_error((exited_zero
                                  ? "ffmpeg reported an error (though it exited 0)"
                                  : "ffmpeg failed (" + describe_status(result.status) + ")") +
                             " making " + video.string() + ": " + trimmed(result.errors));
  }
}

// A two-frame video of the same kind, made in a hidden folder beside the output (whose folder
// was checked writable): a container or codec this ffmpeg cannot write (`--video out.xyz`),
// or an image format that holds one frame (`--video out.png`), is found before a run, not
// after it. A probe that cannot be set up (the folder is not writable after all) checks
// nothing: the real video will say what is wrong.
void probe_video_kind(const std::filesystem::path& program, const std::filesystem::path& output,
                      const VideoOptions& options) {
  const std::filesystem::path folder =
      (output.has_parent_path() ? output.parent_path() : std::filesystem::path(".")) /
      ("." + output.stem().string() + ".probe." + std::to_string(::getpid()));
  struct Remove {
    std::filesystem::path folder;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } remove{folder};
  constexpr int kSide = 16;
  try {
    std::filesystem::create_directories(folder);
    for (const char* frame : {"frame_000000.png", "frame_000001.png"})
      write_png(folder / frame, kSide, kSide, std::vector<std::uint8_t>(kSide * kSide * 4, 255), 1);
  } catch (const std::exception&) {
    return;
  }
  try {
    make_video(program, options, folder, folder / ("probe" + output.extension().string()), output);
  } catch (const std::runtime_error& e) {
    throw InputError("video output '" + output.string() + "': ffmpeg cannot make a " +
                     output.extension().string() + " video of the frames: " + e.what());
  }
}

}  // namespace

std::filesystem::path check_video_request(const std::filesystem::path& output,
                                          const VideoOptions& options) {
  const std::filesystem::path program = video_program(output, options);
  probe_video_kind(program, output, options);
  return program;
}

void assemble_video(const std::filesystem::path& frames_dir, const std::filesystem::path& output,
                    const VideoOptions& options) {
  if (std::error_code error; !std::filesystem::is_directory(frames_dir, error)) {
    throw InputError(
        frames_dir.string() +
        (std::filesystem::exists(frames_dir, error) ? ": is not a folder" : ": no such folder") +
        " (expected the frames of a run: `swarmagg run WORLD --render-every K` or "
        "`swarmagg render`)");
  }
  if (!std::filesystem::exists(frames_dir / "frame_000000.png")) {
    throw InputError("no frames to assemble in " + frames_dir.string() +
                     " (expected frame_000000.png, frame_000001.png, ...)");
  }
  check_frames_contiguous(frames_dir);
  // The request checked as `run --video` checks it, so that a container ffmpeg cannot make is
  // bad input (exit 2) here too, not a failed ffmpeg run.
  const std::filesystem::path program = check_video_request(output, options);
  if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
  const auto temporary =
      output.parent_path() / ("." + output.stem().string() + "." + std::to_string(::getpid()) +
                              ".tmp" + output.extension().string());
  const auto stop_if_requested = [&] {
    if (!options.stop_requested || !options.stop_requested()) return;
    discard_temporary(temporary);
    throw std::runtime_error("stopped: " + output.string() + " not written");
  };
  stop_if_requested();
  make_video(program, options, frames_dir, temporary, output);
  stop_if_requested();
  rename_or_discard(temporary, output);
}

}  // namespace swarmagg
