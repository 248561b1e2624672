#include "python/bindings.hpp"
#include "swarmagg_version.hpp"

PYBIND11_MODULE(_core, module) {
  module.doc() = "swarmagg's simulator, models and sweeps (see the swarmagg package)";
  module.attr("__version__") = SWARMAGG_VERSION;
  swarmagg::python::bind_errors(module);
  swarmagg::python::bind_world(module);
  swarmagg::python::bind_run(module);
  swarmagg::python::bind_simulation(module);
  swarmagg::python::bind_sweep(module);
}
