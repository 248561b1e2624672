#include <cstdlib>

#include "python/bindings.hpp"
#include "swarmagg_version.hpp"

PYBIND11_MODULE(_core, module) {
  // llvmpipe draws a frame on threads it starts at the first frame, which a forked process
  // (multiprocessing's default on Linux) does not have: a worker forked after the parent drew
  // a frame waited for them for ever. Single-threaded, it draws the same pixels. Unless the
  // user chose a number of threads (LP_NUM_THREADS), frames are drawn on the calling thread.
  ::setenv("LP_NUM_THREADS", "0", 0);
  module.doc() = "swarmagg's simulator, models and sweeps (see the swarmagg package)";
  module.attr("__version__") = SWARMAGG_VERSION;
  swarmagg::python::bind_errors(module);
  swarmagg::python::bind_world(module);
  swarmagg::python::bind_run(module);
  swarmagg::python::bind_simulation(module);
  swarmagg::python::bind_sweep(module);
}
