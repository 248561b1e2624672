#include "plot/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "output/atomic_file.hpp"

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

}  // namespace

bool gnuplot_available() {
  return !find_on_path("gnuplot").empty();
}

std::string gnuplot_quote(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

void run_gnuplot(const std::filesystem::path& script_path, const std::string& script) {
  write_file_atomic(script_path, script);
  const auto gnuplot = find_on_path("gnuplot");
  if (gnuplot.empty()) {
    throw std::runtime_error("gnuplot is not installed, so " + script_path.string() +
                             " was written but not drawn; install it with "
                             "'sudo apt-get install gnuplot-nox' and run 'gnuplot " +
                             script_path.filename().string() + "' in its folder");
  }
  // Absolute, because the child changes into the folder before it opens the log file.
  const auto folder = std::filesystem::absolute(script_path).parent_path();
  const auto log = folder / ("." + script_path.filename().string() + ".log");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, folder.c_str());
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  const std::string name = script_path.filename().string();
  std::vector<char*> argv{const_cast<char*>(gnuplot.c_str()), const_cast<char*>(name.c_str()),
                          nullptr};
  pid_t child = 0;
  const int spawned = posix_spawn(&child, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot start gnuplot for " + script_path.string());
  int status = 0;
  waitpid(child, &status, 0);
  const std::string messages = read_text(log);
  std::filesystem::remove(log);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("gnuplot failed on " + script_path.string() + ":\n" + messages);
  }
}

}  // namespace swarmagg
