#pragma once
// Texts between Python and the library: paths as the file system names them (os.fsdecode's
// surrogates for bytes that are not UTF-8), and str values that must be UTF-8 to reach a world.
#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

namespace swarmagg::python {

// A path as Python names it: the file system's encoding, undecodable bytes as surrogates
// (os.fsdecode), so that any path the system allows comes back as the path given.
inline pybind11::str python_path(const std::filesystem::path& path) {
  const std::string& bytes = path.native();
  return pybind11::reinterpret_steal<pybind11::str>(
      PyUnicode_DecodeFSDefaultAndSize(bytes.data(), static_cast<Py_ssize_t>(bytes.size())));
}

// A str as UTF-8; a str holding surrogates (a name os.fsdecode made of bytes that are not
// UTF-8) cannot be, and is refused as bad input naming `what` (ValueError), not as a failed
// cast (RuntimeError).
std::string utf8_text(pybind11::handle text, const std::string& what);

}  // namespace swarmagg::python
