// swarmagg.sweep(): a sweep file run as `swarmagg sweep` runs it unsharded (resumable, into
// its folder, then merged), without plots and without the GIL. The tidy merged files are
// read by python/swarmagg/.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "output/output_check.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"
#include "python/interruptible.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_merge.hpp"
#include "sweep/sweep_runner.hpp"

namespace py = pybind11;

namespace swarmagg::python {
namespace {

py::dict sweep(const std::string& path, std::optional<std::string> out, int threads, bool force) {
  if (threads < 0 || threads > 1024)  // as run.threads and the CLI's sweep --threads
    throw InputError("threads: expected 0 (all cores) to 1024, got " + std::to_string(threads));
  // An empty path would be the working folder, holding the runs before anything refused it.
  if (out && out->empty()) throw InputError("out: expected a path, got ''");
  const SweepPlan plan = reading_file([&] { return load_sweep(path); });
  SweepOptions options;
  options.out = out ? std::filesystem::path(*out) : std::filesystem::path("runs") / plan.name;
  check_output_folder(options.out, out ? "out" : "the sweep folder");
  options.threads = threads;
  options.replace_outdated = force;
  MergeReport merged;
  const SweepReport report = call_interruptibly([&] {
    const SweepReport ran = run_sweep(plan, options);
    merged = merge_sweep({options.out}, options.out);
    return ran;
  });
  std::vector<std::string> removed;
  for (const std::filesystem::path& file : merged.removed) removed.push_back(file.string());
  py::dict result;
  result["name"] = plan.name;
  result["out"] = options.out.string();
  result["runs"] = report.selected;
  result["already_complete"] = report.already_complete;
  result["ran"] = report.ran;
  result["threads"] = report.threads;
  result["wall_seconds"] = report.wall_seconds;
  // The earlier merge's plots and tables this merge outdated (the CLI names them).
  result["removed"] = removed;
  return result;
}

}  // namespace

void bind_sweep(py::module_& module) {
  module.def("sweep", &sweep, py::arg("path"), py::arg("out") = py::none(), py::arg("threads") = 0,
             py::arg("force") = false, "Runs and merges a sweep (see swarmagg.sweep).");
}

}  // namespace swarmagg::python
