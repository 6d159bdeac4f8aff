// The extension `topocut._topocut`: thin adapters over the library (DESIGN.md: python row), like the
// CLI. The package `topocut` (src/python/topocut/__init__.py) re-exports it with signatures.
#include <pybind11/pybind11.h>

#include "python/bindings.h"
#include "topocut/core/error.h"
#include "topocut/core/version.h"

namespace {

// A file the system does not have or refused: OSError(errno, message) becomes FileNotFoundError,
// PermissionError, IsADirectoryError, ... by its errno, as Python's own open() raises them.
void raise_file_error(const topocut::FileError& e) {
  namespace py = pybind11;
  const py::object error = py::reinterpret_borrow<py::object>(PyExc_OSError)(
      e.error_number(), topocut::one_line_message(e.what()), e.path());
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
}

}  // namespace

PYBIND11_MODULE(_topocut, m) {
  m.doc() = "The compiled part of the topocut package; import topocut instead.";
  m.attr("__version__") = TOPOCUT_VERSION;
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const topocut::FileError& e) {
      raise_file_error(e);
    } catch (const topocut::Error& e) {
      PyErr_SetString(PyExc_ValueError, topocut::one_line_message(e.what()).c_str());
    }
  });
  topocut::python::bind_segmentation(m);
  topocut::python::bind_geometry(m);
  topocut::python::bind_evaluation(m);
  topocut::python::bind_training(m);
  topocut::python::bind_simulation(m);
  topocut::python::bind_keywords(m);
}
