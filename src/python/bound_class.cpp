#include "python/bound_class.hpp"

namespace swarmagg::python {

void refuse_uninitialised(const std::string& bound_class) {
  throw pybind11::type_error(bound_class + " object is not initialised: it was made by __new__() " +
                             "without __init__(), so it holds nothing to use");
}

}  // namespace swarmagg::python
