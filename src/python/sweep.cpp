// swarmagg.sweep(): a sweep file run as `swarmagg sweep` runs it unsharded (resumable, into
// its folder, then merged), without plots and without the GIL. The tidy merged files are
// read by python/swarmagg/.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "output/output_check.hpp"
#include "python/bindings.hpp"
#include "python/errors.hpp"
#include "python/interruptible.hpp"
#include "python/python_text.hpp"
#include "python/world.hpp"
#include "sweep/sweep_loader.hpp"
#include "sweep/sweep_merge.hpp"
#include "sweep/sweep_runner.hpp"

namespace py = pybind11;

namespace swarmagg::python {
namespace {

// Paths as filesystem paths (str, bytes or os.PathLike, any bytes the system allows), not
// UTF-8 text.
py::dict sweep(const std::filesystem::path& path, std::optional<std::filesystem::path> out,
               const py::object& threads_given, bool force) {
  // An integer as run()'s threads is (a bool is a TypeError), checked for range here.
  const YAML::Node threads_node = yaml_index(threads_given, "threads");
  const auto threads = threads_node.as<long long>(-1);
  if (threads < 0 || threads > 1024)  // as run.threads and the CLI's sweep --threads
    throw InputError("threads: expected 0 (all cores) to 1024, got " + threads_node.Scalar());
  // An empty path would be the working folder, holding the runs before anything refused it.
  if (out && out->empty()) throw InputError("out: expected a path, got ''");
  const SweepPlan plan = reading_file([&] { return load_sweep(path.string()); });
  SweepOptions options;
  options.out = out ? *out : std::filesystem::path("runs") / plan.name;
  check_output_folder(options.out, out ? "out" : "the sweep folder");
  options.threads = static_cast<int>(threads);
  options.replace_outdated = force;
  MergeReport merged;
  const SweepReport report = call_interruptibly([&] {
    const SweepReport ran = run_sweep(plan, options);
    merged = merge_sweep({options.out}, options.out);
    return ran;
  });
  py::list removed;
  for (const std::filesystem::path& file : merged.removed) removed.append(python_path(file));
  py::dict result;
  result["name"] = plan.name;
  result["out"] = python_path(options.out);
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
  module.def("sweep", &sweep, py::arg("path"), py::arg("out") = py::none(),
             py::arg("threads") = py::int_(0), py::arg("force") = false,
             "Runs and merges a sweep (see swarmagg.sweep).");
}

}  // namespace swarmagg::python
