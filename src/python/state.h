#pragma once
// The value behind a bound object, checked. pybind11 lets cls.__new__(cls) make an object whose value
// was never constructed (it hands out raw memory for it on first use); only a constructor or
// __setstate__ fills it. Every method and property of the module's types reads its value through
// state_of(), so that such an object raises TypeError instead of reading garbage, and every
// __setstate__ checks the state it is given (pickle_error()), so that no object holds a state its
// methods cannot take.
#include <string>

#include <pybind11/pybind11.h>

#include "topocut/core/error.h"

namespace topocut::python {

namespace py = pybind11;

// self's T, constructed; TypeError if self is no T or holds nothing (made by __new__ alone).
template <typename T>
T& state_of(const py::handle& self) {
  if (!py::isinstance<T>(self)) throw py::type_error("expected a " + py::str(py::type::of<T>().attr("__qualname__")).cast<std::string>());
  auto* instance = reinterpret_cast<py::detail::instance*>(self.ptr());
  py::detail::value_and_holder value = instance->get_value_and_holder(py::detail::get_type_info(typeid(T)));
  if (!value || !value.holder_constructed())
    throw py::type_error("this topocut." + py::str(py::type::of<T>().attr("__qualname__")).cast<std::string>() +
                         " holds nothing: it was made by __new__ without a state (pickle.loads() and the module's "
                         "functions make usable ones)");
  return *value.value_ptr<T>();
}

// A property that reads f(T) of a constructed object.
template <typename T, typename F>
py::cpp_function getter(F f) {
  return py::cpp_function([f](const py::object& self) { return f(state_of<T>(self)); });
}

// The Error of a state __setstate__ cannot take: "not a topocut.<type> state: <why>".
inline Error pickle_error(const std::string& type, const std::string& why) {
  return Error("not a topocut." + type + " state: " + why);
}

}  // namespace topocut::python
