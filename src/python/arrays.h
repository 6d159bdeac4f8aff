#pragma once
// numpy <-> library values for the Python module: grid arrays, point lists, rings. Every check
// raises topocut::Error (ValueError in Python) with one line naming the argument.
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "topocut/core/geometry.h"
#include "topocut/core/grid_array.h"

namespace topocut::python {

namespace py = pybind11;

// A GridArray viewing grid (2-D int8 -> kOccupancy, uint8 -> kGrey; columns contiguous, rows any
// stride). grid must stay alive while the view is used.
GridArray grid_view(const py::array& grid);

// grid_view() of a copy of grid's cells kept in storage: taken while the caller holds the GIL, so
// that no Python thread can change or free the cells (ndarray.resize(refcheck=False)) while the
// library reads them with the GIL released.
GridArray grid_copy(const py::array& grid, std::vector<unsigned char>& storage);

// An (n, 2) float array of the points.
py::array_t<double> points_array(const std::vector<Point2>& points);

// Points from an (n, 2) array-like of numbers; name is the argument's name for errors.
std::vector<Point2> points_from(const py::handle& points, const std::string& name);

// A one-dimensional float array from an array-like (angles, ranges).
std::vector<double> values_from(const py::handle& values, const std::string& name);

}  // namespace topocut::python
