// Every malformed world in tests/data/bad/ is refused with the message it must produce, by
// the loader and by the `swarmagg` binary (exit code 2), never with a crash or a hang.
//   <name>.yaml      the world file;
//   <name>.expected  substrings the message must contain, one a line ('#' starts a comment);
//                    a line "@run-only" marks a world the loader accepts but `swarmagg run`
//                    must refuse (a limit only the chosen engine knows);
//   <name>.set       optional `--set` overrides, one a line.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "config/world_loader.hpp"
#include "core/errors.hpp"

extern char** environ;

namespace swarmagg {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kBadDir = fs::path(SWARMAGG_SOURCE_DIR) / "tests" / "data" / "bad";

std::vector<std::string> lines_of(const fs::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.front() != '#') lines.push_back(line);
  }
  return lines;
}

struct BadWorld {
  std::string name;
  std::vector<std::string> expected;  // substrings of the message
  std::vector<std::string> overrides;
  bool run_only = false;

  fs::path path() const { return kBadDir / (name + ".yaml"); }
};

// gtest names a failing parameter by this.
void PrintTo(const BadWorld& world, std::ostream* out) {
  *out << world.name << ".yaml";
}

std::vector<BadWorld> bad_worlds() {
  std::vector<BadWorld> worlds;
  for (const auto& entry : fs::directory_iterator(kBadDir)) {
    if (entry.path().extension() != ".yaml") continue;
    BadWorld world{entry.path().stem().string(), {}, {}, false};
    for (const std::string& line : lines_of(kBadDir / (world.name + ".expected"))) {
      if (line == "@run-only") {
        world.run_only = true;
      } else {
        world.expected.push_back(line);
      }
    }
    if (fs::exists(kBadDir / (world.name + ".set"))) {
      world.overrides = lines_of(kBadDir / (world.name + ".set"));
    }
    worlds.push_back(std::move(world));
  }
  std::sort(worlds.begin(), worlds.end(),
            [](const BadWorld& a, const BadWorld& b) { return a.name < b.name; });
  return worlds;
}

struct Outcome {
  int exit_code = -1;     // -1 unless the process exited normally
  int signal_number = 0;  // the signal that ended it, if one did
  bool timed_out = false;
  std::string output;  // stdout and stderr together
};

// Runs a program without a shell (arguments hold any bytes), killing it after `limit`.
Outcome run_program(const std::vector<std::string>& arguments, std::chrono::seconds limit) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return {};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  Outcome outcome;
  if (spawned != 0) {
    close(pipe_fds[0]);
    outcome.output = "cannot start " + arguments[0];
    return outcome;
  }
  const auto deadline = std::chrono::steady_clock::now() + limit;
  pollfd reader{pipe_fds[0], POLLIN, 0};
  char buffer[4096];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      outcome.timed_out = true;
      kill(pid, SIGKILL);
      break;
    }
    if (poll(&reader, 1, static_cast<int>(left.count())) <= 0) continue;
    const ssize_t got = read(pipe_fds[0], buffer, sizeof buffer);
    if (got <= 0) break;
    outcome.output.append(buffer, static_cast<std::size_t>(got));
  }
  close(pipe_fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) outcome.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) outcome.signal_number = WTERMSIG(status);
  return outcome;
}

std::string test_name(const ::testing::TestParamInfo<BadWorld>& info) {
  std::string name = info.param.name;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
  return name;
}

class BadWorlds : public ::testing::TestWithParam<BadWorld> {};

TEST_P(BadWorlds, TheLoaderRefusesThemWithTheExpectedMessage) {
  const BadWorld& world = GetParam();
  ASSERT_FALSE(world.expected.empty()) << world.name << ".expected lists no message";
  if (world.run_only) {
    EXPECT_NO_THROW(load_world(world.path().string(), world.overrides))
        << "marked @run-only but the loader refuses it";
    return;
  }
  try {
    load_world(world.path().string(), world.overrides);
    ADD_FAILURE() << world.name << " was accepted";
  } catch (const InputError& e) {
    for (const std::string& part : world.expected) EXPECT_THAT(e.what(), HasSubstr(part));
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw " << typeid(e).name() << " (" << e.what() << "), not an InputError";
  }
}

TEST_P(BadWorlds, TheBinaryExitsTwoWithTheMessageAndWritesNothing) {
  const BadWorld& world = GetParam();
  ASSERT_TRUE(fs::exists(SWARMAGG_BINARY)) << "build swarmagg first";
  const fs::path out = fs::temp_directory_path() / ("swarmagg-bad-" + world.name);
  fs::remove_all(out);
  std::vector<std::string> arguments = {SWARMAGG_BINARY, "run",   world.path().string(),
                                        "--quiet",       "--out", out.string()};
  for (const std::string& o : world.overrides) {
    arguments.push_back("--set");
    arguments.push_back(o);
  }
  const Outcome o = run_program(arguments, std::chrono::seconds(60));
  ASSERT_FALSE(o.timed_out) << world.name << " hangs";
  ASSERT_EQ(o.signal_number, 0) << world.name << " crashed:\n" << o.output;
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_THAT(o.output, HasSubstr("swarmagg: "));
  for (const std::string& part : world.expected) EXPECT_THAT(o.output, HasSubstr(part));
  EXPECT_FALSE(fs::exists(out)) << "a refused world left an output folder";
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Collection, BadWorlds, ::testing::ValuesIn(bad_worlds()), test_name);

TEST(BadWorldCollection, EveryWorldHasItsMessageAndEveryKindIsCovered) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kBadDir)) {
    const fs::path p = entry.path();
    if (p.extension() == ".yaml") {
      EXPECT_TRUE(fs::exists(fs::path(p).replace_extension(".expected"))) << p;
      names.push_back(p.stem().string());
    } else {
      EXPECT_TRUE(fs::exists(fs::path(p).replace_extension(".yaml"))) << p << " has no world";
    }
  }
  // The kinds issue 10 names: syntax errors, wrong types, unknown keys, impossible values,
  // huge numbers, NaN and infinities, empty files, binary garbage, deep nesting, --set.
  for (const char* kind : {"syntax-", "type-", "key-", "value-", "huge-", "nan-", "inf-", "empty",
                           "garbage-", "deep-", "set-"}) {
    const auto count = std::count_if(
        names.begin(), names.end(), [kind](const std::string& n) { return n.rfind(kind, 0) == 0; });
    EXPECT_GE(count, 2) << "too few bad worlds of kind " << kind;
  }
}

// Worlds next to the bad ones that must still load: the fixes refuse no more than they should.
TEST(BadWorldNeighbours, StillLoad) {
  EXPECT_NO_THROW(load_world_text("robots: {count: 5}\n---\n", "trailing-marker.yaml"));
  EXPECT_NO_THROW(load_world_text("robots: {count: 5}\nrender: {dir: 'a, b'}\n", "comma.yaml"));
  // Bodies that touch do not overlap, across the torus seam too.
  EXPECT_NO_THROW(load_world_text("robots: {placement: [[10, 10, 0], [12, 10, 0]]}\n", "t.yaml"));
  EXPECT_NO_THROW(load_world_text("robots: {placement: [[1, 50, 0], [179, 50, 0]]}\n", "s.yaml"));
  EXPECT_NO_THROW(load_world_text("arena: {width: 1000000, height: 10}\n", "wide.yaml"));
  EXPECT_NO_THROW(load_world_text("run: {duration: 100000000000}\n", "long.yaml"));
}

}  // namespace
}  // namespace swarmagg
