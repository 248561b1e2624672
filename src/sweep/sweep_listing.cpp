#include "sweep/sweep_listing.hpp"

#include <cstdio>

#include "sweep/sweep_status.hpp"

namespace swarmagg {

std::string sweep_listing(const std::vector<SweepRun>& runs, const std::filesystem::path& out) {
  char line[96];
  std::snprintf(line, sizeof line, "%6s %9s %20s %-10s  %s\n", "run", "replicate", "seed", "status",
                "parameters");
  std::string text = line;
  for (const SweepRun& run : runs) {
    std::snprintf(line, sizeof line, "%6d %9d %20llu %-10s  ", run.index, run.replicate,
                  static_cast<unsigned long long>(run.seed),
                  status_name(sweep_run_status(out, run)));
    text += line + describe_point(run.point) + "\n";
  }
  return text;
}

}  // namespace swarmagg
