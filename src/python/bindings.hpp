#pragma once
// The Python module `swarmagg._core`: a thin layer over the library the CLI uses. Each file
// binds one concept; python/swarmagg/ turns the texts these return (the CLI's own CSV and
// JSON) into pandas frames and dicts, so the two doors cannot disagree on a column.
#include <pybind11/pybind11.h>

namespace swarmagg::python {

void bind_errors(pybind11::module_& module);
void bind_world(pybind11::module_& module);
void bind_run(pybind11::module_& module);
void bind_simulation(pybind11::module_& module);
void bind_sweep(pybind11::module_& module);

}  // namespace swarmagg::python
