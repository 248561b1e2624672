#include "python/errors.hpp"

#include <cstring>
#include <system_error>

#include "python/bindings.hpp"
#include "run/interrupt.hpp"

namespace py = pybind11;

namespace swarmagg::python {
namespace {

// A message as a Python str. It may hold bytes that are not UTF-8 (a world file in Latin-1, a
// path with such a name): decoded strictly, the exception came out empty, or as a
// UnicodeDecodeError; those bytes are shown escaped instead.
py::object message(const char* text) {
  PyObject* decoded =
      PyUnicode_DecodeUTF8(text, static_cast<Py_ssize_t>(std::strlen(text)), "backslashreplace");
  if (decoded == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(decoded);
}

}  // namespace

void bind_errors(py::module_& module) {
  // Never destroyed: its destructor would run after the interpreter is gone.
  static auto* world_error =
      new py::exception<FileInputError>(module, "WorldError", PyExc_ValueError);
  world_error->attr("__doc__") =
      "A world or sweep file, or a `set` key, is wrong. The message is the CLI's: the file, "
      "the line, the key and what was expected. A subclass of ValueError.";
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const FileInputError& e) {
      PyErr_SetObject(world_error->ptr(), message(e.what()).ptr());
    } catch (const InputError& e) {
      PyErr_SetObject(PyExc_ValueError, message(e.what()).ptr());
    } catch (const Interrupted&) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const std::system_error& e) {
      // OSError(errno, message) picks the subclass a Python caller expects (IsADirectoryError,
      // PermissionError, FileNotFoundError, ...).
      const int number = e.code().category() == std::generic_category() ||
                                 e.code().category() == std::system_category()
                             ? e.code().value()
                             : 0;
      PyErr_SetObject(PyExc_OSError, py::make_tuple(number, message(e.what())).ptr());
    }
  });
}

}  // namespace swarmagg::python
