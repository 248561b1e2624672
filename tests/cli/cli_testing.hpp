#pragma once
// Helpers of the tests that run the built `swarmagg` binary as a user would.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swarmagg::testing {

struct CliOutcome {
  int exit_code = -1;  // -1 unless the process exited normally
  std::string output;  // stdout and stderr together
};

// Runs `swarmagg <arguments>` through the shell and waits for it; `environment` holds
// assignments for the child only (e.g. "PATH=/x"); `stdout_to`, a file that takes standard
// output instead of `output` (which then holds stderr alone).
inline CliOutcome run_swarmagg(const std::string& arguments, const std::string& environment = "",
                               const std::string& stdout_to = "") {
  const std::string redirection = stdout_to.empty() ? " 2>&1" : " 2>&1 >" + stdout_to;
  const std::string command =
      environment + " " + std::string(SWARMAGG_BINARY) + " " + arguments + redirection;
  CliOutcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return outcome;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

inline std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace swarmagg::testing
