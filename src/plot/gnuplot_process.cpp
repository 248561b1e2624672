#include "plot/gnuplot_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace swarmagg {
namespace {

std::filesystem::path find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path ? path : "/usr/bin:/bin");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    const auto candidate = std::filesystem::path(folder.empty() ? "." : folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Unique among the processes and threads that may draw into one folder at once.
std::filesystem::path log_file(const std::filesystem::path& folder,
                               const std::filesystem::path& command_file) {
  static std::atomic<unsigned> counter{0};
  return folder / ("." + command_file.filename().string() + "." + std::to_string(::getpid()) + "-" +
                   std::to_string(counter++) + ".log");
}

}  // namespace

std::filesystem::path find_gnuplot() {
  return find_on_path("gnuplot");
}

std::string gnuplot_missing_message(const std::filesystem::path& script_path) {
  return "gnuplot is not installed, so " + script_path.string() +
         " was written but not drawn; install it with 'sudo apt-get install gnuplot-nox' and "
         "run 'gnuplot " +
         script_path.filename().string() + "' in its folder";
}

GnuplotExit run_gnuplot_process(const std::filesystem::path& command_file,
                                const std::filesystem::path& folder) {
  const auto gnuplot = find_gnuplot();
  if (gnuplot.empty()) throw std::runtime_error(gnuplot_missing_message(command_file));
  // Absolute, because the child changes into the folder before it opens the log file.
  const auto working = std::filesystem::absolute(folder);
  const auto log = log_file(working, command_file);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, working.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  const std::string file = command_file.string();
  std::vector<char*> argv{const_cast<char*>(gnuplot.c_str()), const_cast<char*>(file.c_str()),
                          nullptr};
  pid_t child = 0;
  const int spawned = posix_spawn(&child, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start gnuplot for " + file);
  // A signal (Ctrl-C) interrupts the wait without ending gnuplot's: waited for again. A wait
  // that fails otherwise is a failure, never a success read from an unset status.
  int status = 0;
  pid_t waited = 0;
  do {
    waited = waitpid(child, &status, 0);
  } while (waited < 0 && errno == EINTR);
  if (waited < 0) status = -1;
  GnuplotExit exit{.succeeded = waited > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0,
                   .messages = read_text(log)};
  std::filesystem::remove(log);
  return exit;
}

}  // namespace swarmagg
