#pragma once
// What every class of swarmagg._core does with objects Python makes without __init__, and
// with copy and pickle.
//
// `Cls.__new__(Cls)` makes an object that holds no C++ value. pybind11 2.10 hands such an
// object to a bound function anyway: its caster allocates the value's memory on first use and
// constructs nothing, so a method read garbage (Simulation.step() was a segfault). The caster of
// a class marked BoundToPython refuses it instead, with a TypeError naming the class, whether
// the object comes as `self` or as an argument (run(world)).
//
// copy and pickle, left to their defaults, refuse every class ("cannot pickle"), and pickle's
// protocols 0 and 1 abort the interpreter (copyreg calls pybind11_object(obj), which throws
// from C); each class says instead what they do (copied_as_itself, pickled_by_state,
// refuse_pickling).
#include <pybind11/pybind11.h>

#include <string>
#include <utility>

namespace swarmagg::python {

// A class bound with py::class_ declares `using BoundToPython = void;` so that its caster
// (below) refuses objects without a C++ value. tests/python/test_copies.py checks that every
// class of the module does.
template <typename T>
concept BoundToPython = requires {
  typename T::BoundToPython;
};

// Raises the TypeError of an object of `bound_class` (its Python name) that __init__ never made.
[[noreturn]] void refuse_uninitialised(const std::string& bound_class);

// pybind11's own caster of T, but for objects without a value (load_impl calls load_value
// with the object's value and holder; copyable_holder_caster overrides it the same way, in
// pybind11::detail as of 2.10).
template <BoundToPython T>
class InitialisedOnlyCaster : public pybind11::detail::type_caster_base<T> {
 public:
  bool load(pybind11::handle source, bool convert) {
    return this->template load_impl<InitialisedOnlyCaster>(source, convert);
  }
  void load_value(pybind11::detail::value_and_holder&& held) {
    // Named as the bound class, which a Python subclass's object did not initialise either.
    if (held.value_ptr() == nullptr) refuse_uninitialised(this->typeinfo->type->tp_name);
    pybind11::detail::type_caster_base<T>::load_value(std::move(held));
  }
};

// An immutable class: copy.copy and copy.deepcopy return the object itself, as for a tuple.
template <typename Class>
void copied_as_itself(Class& bound) {
  bound.def("__copy__", [](const pybind11::object& self) { return self; });
  bound.def(
      "__deepcopy__", [](const pybind11::object& self, const pybind11::object&) { return self; },
      pybind11::arg("memo"));
}

namespace detail {
// Binds `reduce(self)` as __reduce_ex__(protocol), through which pickle and copy take an object
// apart, and as __reduce__(), whose default calls pybind11_object(self) for protocols 0 and 1
// (copyreg._reduce_ex), which aborts the interpreter.
template <typename Class, typename Reduce>
void def_reduce(Class& bound, Reduce reduce) {
  bound.def(
      "__reduce_ex__", [reduce](const pybind11::object& self, int) { return reduce(self); },
      pybind11::arg("protocol"));
  bound.def("__reduce__", reduce);
}
}  // namespace detail

// pickle, and copy where the class has no __copy__ or __deepcopy__, raise TypeError(`why`).
template <typename Class>
void refuse_pickling(Class& bound, std::string why) {
  detail::def_reduce(bound, [why = std::move(why)](const pybind11::object&) -> pybind11::object {
    throw pybind11::type_error(why);
  });
}

// pickle keeps `state(object)` and makes the object again with `make(state)` (py::pickle), at
// every protocol: the empty object that __setstate__ fills comes from copyreg.__newobj__, as
// protocols 2 and up would make it.
template <typename Class, typename State, typename Make>
void pickled_by_state(Class& bound, State state, Make make) {
  bound.def(pybind11::pickle(std::move(state), std::move(make)));
  detail::def_reduce(bound, [](const pybind11::object& self) {
    return pybind11::make_tuple(pybind11::module_::import("copyreg").attr("__newobj__"),
                                pybind11::make_tuple(pybind11::type::of(self)),
                                self.attr("__getstate__")());
  });
}

}  // namespace swarmagg::python

namespace pybind11::detail {

template <swarmagg::python::BoundToPython T>
class type_caster<T> : public swarmagg::python::InitialisedOnlyCaster<T> {};

}  // namespace pybind11::detail
