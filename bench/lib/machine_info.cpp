#include "bench/lib/machine_info.hpp"

#include <fstream>
#include <string>
#include <thread>

#include "swarmagg_version.hpp"

namespace swarmagg {
namespace {

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  }
  return "unknown";
}

}  // namespace

nlohmann::json machine_info() {
  return {{"cpu", cpu_model()},
          {"cores", std::thread::hardware_concurrency()},
          {"compiler", std::string("g++ ") + __VERSION__},
          {"build_type", SWARMAGG_BUILD_TYPE},
          {"git", SWARMAGG_GIT_HASH},
          {"swarmagg", SWARMAGG_VERSION}};
}

}  // namespace swarmagg
